"""ocean.bake and ocean.merge called from the main thread stop on SIGINT, SIGTERM and SIGHUP as
`ocean bake` does: between two files, the unfinished frame removed, the manifest saying
"complete": false, no temporary file left. Then SIGINT raises KeyboardInterrupt and SIGTERM and
SIGHUP raise SystemExit(128 + the signal), unless the program's own handler raises first.

Each case runs in a child interpreter, signalled once its first frame is whole in the output
folder. The time limits below only stop a child that never reacts; nothing is timed."""
import json
import os
import signal
import subprocess
import sys
import time

import pytest

FRAMES = 100000  # hours of baking: only a signal ends it within the test
# The first file of the second frame: the first frame is whole once it exists.
SECOND_FRAME_FILE = "displacement_c0_f00001.npy"
CHILD_LIMIT_S = 300

# The child: argv = what (bake or merge), out, then the shard folders to merge; the frames to
# bake in OCEAN_TEST_FRAMES.
# A setting before the call comes through the environment: OCEAN_TEST_SIGNAL_SETUP names a
# signal and what to install for it ("SIGTERM=raise" or "SIGHUP=ignore").
CHILD = r"""
import os, signal, sys
import ocean

what, out, shards = sys.argv[1], sys.argv[2], sys.argv[3:]
setup = os.environ.get("OCEAN_TEST_SIGNAL_SETUP")
if setup:
    name, action = setup.split("=")
    def handler(signum, frame):
        raise RuntimeError(f"the program's own handler of {signal.Signals(signum).name}")
    signal.signal(getattr(signal, name), handler if action == "raise" else signal.SIG_IGN)
p = ocean.Preset("storm").set("resolution=16").set("cascades_m=[300.0, 71.0]")
if what == "merge":
    ocean.merge(shards, out)
elif what == "bake":
    ocean.bake(p, out, frames=int(os.environ["OCEAN_TEST_FRAMES"]), fps=30.0)
print("returned")
"""


def start(what, out, *shards, frames=FRAMES, setup=None):
    env = dict(os.environ, OCEAN_TEST_FRAMES=str(frames))
    if setup:
        env["OCEAN_TEST_SIGNAL_SETUP"] = setup
    return subprocess.Popen([sys.executable, "-c", CHILD, what, str(out), *map(str, shards)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)


def signal_after_first_frame(child, out, sig):
    """Sends `sig` once the second frame's first file is in `out`; returns (returncode, stdout,
    stderr) of the child."""
    deadline = time.monotonic() + CHILD_LIMIT_S
    while not (out / SECOND_FRAME_FILE).exists():
        if child.poll() is not None:
            _, err = child.communicate()
            pytest.fail(f"the child ended before its second frame:\n{err}")
        if time.monotonic() > deadline:
            child.kill()
            child.communicate()
            pytest.fail("no second frame written")
        time.sleep(0.01)
    child.send_signal(sig)
    try:
        stdout, stderr = child.communicate(timeout=CHILD_LIMIT_S)
    except subprocess.TimeoutExpired:
        child.kill()
        child.communicate()
        pytest.fail(f"the child went on after {sig.name}")
    return child.returncode, stdout, stderr


def last_line(text):
    lines = text.strip().splitlines()
    return lines[-1] if lines else ""


def assert_stopped_cleanly(out, frame_count):
    """The manifest says "complete": false and lists frames whose files all exist; nothing
    temporary and no lock remain."""
    names = os.listdir(out)
    assert not [n for n in names if ".tmp-" in n or n == ".ocean-bake.lock"], names
    with open(out / "manifest.json", encoding="utf-8") as f:
        manifest = json.load(f)
    assert manifest["complete"] is False
    assert manifest["stopped"] == "cancelled"
    assert manifest["frame_count"] == frame_count
    listed = [name for frame in manifest["frames"] for name in frame["files"]]
    assert 1 <= manifest["frames_written"] == len(manifest["frames"]) < frame_count
    assert all((out / name).is_file() for name in listed)
    # Only the listed frames' files and the manifest: the unfinished frame's files were removed.
    assert sorted(names) == sorted(listed + ["manifest.json"])
    return manifest


EXPECTED = {
    signal.SIGINT: (-signal.SIGINT, "KeyboardInterrupt: {what} interrupted: SIGINT; {what} "
                                    "cancelled after {n} of {frames} frames; '{manifest}' says "
                                    "\"complete\": false"),
    signal.SIGTERM: (128 + signal.SIGTERM, ""),
    signal.SIGHUP: (128 + signal.SIGHUP, ""),
}


@pytest.mark.parametrize("sig", list(EXPECTED), ids=lambda s: s.name)
def test_bake_stops_on_a_signal(tmp_path, sig):
    out = tmp_path / "bake"
    code, stdout, stderr = signal_after_first_frame(start("bake", out), out, sig)
    manifest = assert_stopped_cleanly(out, FRAMES)
    returncode, line = EXPECTED[sig]
    assert code == returncode, stderr
    assert "returned" not in stdout
    assert last_line(stderr) == line.format(what="bake", n=manifest["frames_written"],
                                            frames=FRAMES, manifest=out / "manifest.json")


def test_bake_raises_what_the_programs_own_handler_raises(tmp_path):
    out = tmp_path / "bake"
    child = start("bake", out, setup="SIGTERM=raise")
    code, _, stderr = signal_after_first_frame(child, out, signal.SIGTERM)
    assert_stopped_cleanly(out, FRAMES)
    assert code == 1
    assert last_line(stderr) == "RuntimeError: the program's own handler of SIGTERM"


def test_an_ignored_signal_stays_ignored(tmp_path):
    # As under nohup: SIGHUP ignored before the call is not turned into a cancellation.
    out = tmp_path / "bake"
    child = start("bake", out, frames=6, setup="SIGHUP=ignore")
    code, stdout, stderr = signal_after_first_frame(child, out, signal.SIGHUP)
    assert code == 0, stderr
    assert stdout.strip() == "returned"
    with open(out / "manifest.json", encoding="utf-8") as f:
        assert json.load(f)["complete"] is True


def test_handlers_are_restored_after_the_call(tmp_path):
    # After the bake SIGTERM has its default action again: it ends the process.
    script = CHILD + "os.kill(os.getpid(), signal.SIGTERM)\nprint('alive')\n"
    r = subprocess.run([sys.executable, "-c", script, "bake", str(tmp_path / "b")],
                       capture_output=True, text=True, timeout=CHILD_LIMIT_S,
                       env=dict(os.environ, OCEAN_TEST_FRAMES="1"), check=False)
    assert r.returncode == -signal.SIGTERM, r.stderr
    assert r.stdout.strip() == "returned"


SHARD_FRAMES = 40


@pytest.fixture(scope="module")
def shards(tmp_path_factory):
    import ocean

    root = tmp_path_factory.mktemp("shards")
    p = ocean.Preset("storm").set("resolution=16").set("cascades_m=[300.0, 71.0]")
    dirs = [root / f"s{i}" for i in range(2)]
    for i, d in enumerate(dirs):
        ocean.bake(p, d, frames=SHARD_FRAMES, fps=30.0, shard=f"{i}/2")
    return dirs


@pytest.mark.parametrize("sig", list(EXPECTED), ids=lambda s: s.name)
def test_merge_stops_on_a_signal(tmp_path, shards, sig):
    out = tmp_path / "merged"
    code, stdout, stderr = signal_after_first_frame(start("merge", out, *shards), out, sig)
    manifest = assert_stopped_cleanly(out, SHARD_FRAMES)
    returncode, line = EXPECTED[sig]
    assert code == returncode, stderr
    assert "returned" not in stdout
    assert last_line(stderr) == line.format(what="merge", n=manifest["frames_written"],
                                            frames=SHARD_FRAMES, manifest=out / "manifest.json")
