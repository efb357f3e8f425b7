"""Every argument is checked against the range the library takes: a value out of range, however
large, raises ValueError naming the argument and its range (the tool's message where the tool
has the flag), never crashes, wraps around or fails the conversion with a TypeError."""
import json

import numpy as np
import pytest

import ocean

HUGE = [10**9, 2**31, 2**63, 10**30, -(2**63) - 1]


@pytest.mark.parametrize("indent", [65, 600, 100000, 2**31, 10**30])
def test_preset_indent_beyond_its_range(indent):
    # nlohmann::json 3.11.2 grows its 512-space indentation string once per level: an indent
    # above 512 read past it (a crash for 100000).
    with pytest.raises(ValueError, match=rf"^indent = {indent} is out of range: must be an "
                                         r"integer in \[0, 64\]"):
        ocean.Preset("calm").to_json(indent=indent)


def test_preset_indent_in_range():
    p = ocean.Preset("calm")
    assert json.loads(p.to_json(indent=64)) == json.loads(p.to_json())
    assert "\n" + " " * 64 + '"sea"' in p.to_json(indent=64)
    for compact in (-1, -5, -(10**30)):  # negative: one line
        assert p.to_json(indent=compact) == p.to_json(indent=-1)
        assert "\n" not in p.to_json(indent=compact)
    assert p.to_json(indent=np.int64(3)) == p.to_json(indent=3)
    with pytest.raises(TypeError):
        p.to_json(indent=2.0)


@pytest.mark.parametrize("threads", HUGE + [-1, 257])
def test_simulator_threads_beyond_its_range(small_preset, threads):
    # oneTBB crashed on the first step of an arena of 10**9 threads.
    with pytest.raises(ValueError, match=rf"^threads = {threads} is out of range: must be an "
                                         r"integer in \[0, 256\] \(0: all threads\)$"):
        ocean.Simulator(small_preset, threads=threads)


def test_simulator_threads_in_range(small_preset):
    for threads in (0, 1, 256):
        sim = ocean.Simulator(small_preset, threads=threads)
        sim.step(1.0)
        assert np.isfinite(sim.fields(0)["height"]).all()


@pytest.mark.parametrize("threads", [10**9, -1, 2**63])
def test_surface_stats_threads_beyond_its_range(threads):
    with pytest.raises(ValueError, match=rf"^threads = {threads} is out of range"):
        ocean.surface_stats("calm", seeds=1, threads=threads)


@pytest.mark.parametrize("seeds", [0, 100001, 2**31, 2**64])
def test_surface_stats_seeds_as_the_tool(seeds, cli_message):
    with pytest.raises(ValueError) as e:
        ocean.surface_stats("calm", seeds=seeds)
    assert str(e.value) == (f"seeds = {seeds} is out of range: must be an integer in "
                            "[1, 100000]")
    tool = cli_message("stats", "--seeds", str(seeds))
    if tool is not None:
        assert str(e.value) == tool


@pytest.mark.parametrize("cascade", [2**31, 2**63, -(2**31) - 1, 10**30])
def test_fields_cascade_beyond_its_range(small_preset, cascade):
    sim = ocean.Simulator(small_preset)
    with pytest.raises(ValueError, match=rf"^cascade = {cascade} is out of range: must be an "
                                         r"integer in \[0, 1\]$"):
        sim.fields(cascade)


@pytest.mark.parametrize("args,message", [
    ((2**62, 3, 4), r"^frames = 4611686018427387904 is out of range: must be an integer in "
                    r"\[1, 1000000\]$"),
    ((2**62, 2**61 - 1, 2**62), r"^frames = 4611686018427387904 is out of range"),
    ((10**30, 0, 1), r"^frames = 1000000000000000000000000000000 is out of range"),
    ((0, 0, 1), r"^frames = 0 is out of range"),
    ((10, 0, 11), r"^count = 11 is out of range: must be an integer in \[1, 10\]$"),
    ((10, 0, 2**63), r"^count = 9223372036854775808 is out of range"),
    ((10, 0, 0), r"^count = 0 is out of range"),
    ((10, 3, 3), r"^index = 3 is out of range: must be an integer in \[0, 2\]$"),
    ((10, -1, 3), r"^index = -1 is out of range"),
    ((10, -(2**64), 3), r"^index = -18446744073709551616 is out of range"),
])
def test_shard_frames_beyond_its_range(args, message):
    # index * frames overflowed: shard 3 of 4 of 2**62 frames came back as negative frames.
    with pytest.raises(ValueError, match=message):
        ocean.shard_frames(*args)


def test_shard_frames_at_the_bounds():
    n = 1000000
    assert ocean.shard_frames(n, n - 1, n) == (n - 1, n)
    blocks = [ocean.shard_frames(n, i, 7) for i in range(7)]
    assert blocks[0][0] == 0 and blocks[-1][1] == n
    assert all(a[1] == b[0] for a, b in zip(blocks, blocks[1:]))


@pytest.mark.parametrize("frames", [2**63, 10**30, -(2**63) - 1])
def test_bake_frames_beyond_64_bits(tmp_path, frames):
    with pytest.raises(ValueError) as e:
        ocean.bake("calm", tmp_path / "b", frames=frames)
    assert str(e.value) == (f"frames = {frames} is out of range: must be an integer in "
                            "[1, 1000000]")
    assert not (tmp_path / "b").exists()


def test_surface_stats_time_as_the_tool(cli_message):
    with pytest.raises(ValueError) as e:
        ocean.surface_stats("calm", seeds=1, time=float("inf"))
    assert str(e.value) == "time = inf is out of range: must be a finite number"
    tool = cli_message("stats", "--seeds", "1", "--time", "inf")
    if tool is not None:
        assert str(e.value) == tool


@pytest.mark.parametrize("name", ["s", "alpha"])
def test_spreading_nan_as_the_tool(name, cli_message):
    keywords = {"s": 10.0, name: float("nan")}
    with pytest.raises(ValueError) as e:
        ocean.spreading([0.0], model="cos2s", **keywords)
    assert str(e.value) == f"{name} = nan is out of range: must be a finite number"
    flags = [a for k, v in keywords.items() for a in (f"--{k}", str(v))]
    tool = cli_message("spreading", "--model", "cos2s", *flags, "--theta", "0")
    if tool is not None:
        assert str(e.value) == tool
