"""Bad input raises the exception of its Status (ValueError, OSError, ...) with the one-line
message `ocean` prints for the same input, in Python's names (compared with the tool itself when
it is built); a call the extension cannot match raises a one-line TypeError."""
import re

import numpy as np
import pytest

import ocean

# (the Python call, the same input to the tool, the message)
CASES = [
    (lambda: ocean.spectrum("jonswap", omega=[1.0], hs=-1.0, tp=8.0),
     ["spectrum", "--hs", "-1", "--tp", "8", "--omega", "1"],
     "hs = -1 is out of range: must be in [1e-06, 50]"),
    (lambda: ocean.spectrum("jonswap", omega=[1.0], gamma=0.5),
     ["spectrum", "--gamma", "0.5", "--omega", "1"], None),
    (lambda: ocean.spectrum("waves", omega=[1.0]),
     ["spectrum", "--model", "waves", "--omega", "1"], None),
    (lambda: ocean.spectrum("jonswap", omega=[-2.0]),
     ["spectrum", "--omega", "-2"], None),
    (lambda: ocean.spectrum("tma", omega=[1.0], hs=2.0, tp=8.0),
     ["spectrum", "--model", "tma", "--hs", "2", "--tp", "8", "--omega", "1"],
     "tma needs depth (water depth, m)"),
    (lambda: ocean.dispersion(k=[1.0], omega=[1.0]),
     ["dispersion", "--k", "1", "--omega", "1"],
     "dispersion needs exactly one of k=K1,... or omega=W1,..."),
    (lambda: ocean.dispersion(k=[1.0], depth=-3.0),
     ["dispersion", "--k", "1", "--depth", "-3"], None),
    (lambda: ocean.spreading([0.0], model="mitsuyasu"),
     ["spreading", "--model", "mitsuyasu", "--theta", "0"],
     "mitsuyasu spreading needs wind_speed=MPS fetch=M"),
    (lambda: ocean.spreading([0.0], model="cos2s", s=-1.0),
     ["spreading", "--model", "cos2s", "--s", "-1", "--theta", "0"], None),
]


@pytest.mark.parametrize("call,args,message", CASES)
def test_value_error_has_the_tools_message(call, args, message, cli_message):
    with pytest.raises(ValueError) as e:
        call()
    text = str(e.value)
    assert "\n" not in text and text
    if message is not None:
        assert text == message
    tool = cli_message(*args)
    if tool is not None:
        assert text == tool


def test_preset_errors(tmp_path, cli_message):
    with pytest.raises(OSError) as e:
        ocean.Preset(str(tmp_path / "missing.json"))
    assert "missing.json" in str(e.value)
    with pytest.raises(ValueError) as e:
        ocean.Preset("stormy")
    assert str(e.value).startswith("preset = stormy is neither a file nor a preset")
    p = ocean.Preset("calm")
    before = p.to_json()
    with pytest.raises(ValueError) as e:
        p.set("resolution=17")
    assert p.to_json() == before  # a failed set leaves the preset as it was
    tool = cli_message("stats", "--set", "resolution=17")
    if tool is not None:
        assert str(e.value) == tool
    with pytest.raises(ValueError, match="expected key=value"):
        p.set("resolution")


def test_simulator_and_query_errors(small_preset):
    with pytest.raises(ValueError, match="is unknown"):
        ocean.Simulator(small_preset, backend="abacus")
    sim = ocean.Simulator(small_preset)
    with pytest.raises(ValueError, match=r"xz must be an \(n, 2\) array"):
        sim.heights(np.zeros((4, 3)))
    with pytest.raises(ValueError, match="time_s = nan"):
        sim.step(float("nan"))
    with pytest.raises(ValueError, match="cascade = 5 is out of range"):
        sim.fields(5)


def test_bake_errors(tmp_path, small_preset):
    with pytest.raises(ValueError) as e:
        ocean.bake(small_preset, tmp_path / "b", formats=["tiff"])
    assert str(e.value) == "formats: 'tiff' is unknown: must be exr, png or npy"
    with pytest.raises(ValueError, match="^shard = '3/2' is not I/N"):
        ocean.bake(small_preset, tmp_path / "b", frames=2, shard="3/2")
    with pytest.raises(ValueError, match="merge needs at least one shard folder"):
        ocean.merge([], tmp_path / "m")


def test_no_message_names_a_flag():
    for call, _, _ in CASES:
        with pytest.raises(ValueError) as e:
            call()
        assert "--" not in str(e.value), str(e.value)


@pytest.mark.parametrize("call,message", [
    (lambda: ocean.spectrum("jonswap", omega=[1.0], hss=2.0),
     "spectrum() got an unexpected keyword argument 'hss'; did you mean 'hs'? (keywords: model, "
     "omega, hs, tp, wind_speed, fetch, gamma, depth, gravity, depth_factor, fetch_law, "
     "normalization, phillips_amplitude, cutoff_length)"),
    (lambda: ocean.Simulator("calm", threds=2),
     "Simulator() got an unexpected keyword argument 'threds'; did you mean 'threads'? "
     "(keywords: preset, backend, threads)"),
    (lambda: ocean.Simulator("calm").step(t=1.0),
     "Simulator.step() got an unexpected keyword argument 't' (keywords: time_s)"),
    (lambda: ocean.spectrum("jonswap", omega=[1.0], hs="two"),
     "spectrum(): arguments of the wrong type (str, omega=list, hs=str); help(ocean.spectrum) "
     "shows the types"),
])
def test_a_call_that_matches_no_signature_is_one_line(call, message):
    with pytest.raises(TypeError) as e:
        call()
    assert str(e.value) == message


def test_version():
    assert re.fullmatch(r"\d+\.\d+\.\d+", ocean.__version__)
