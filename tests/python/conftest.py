"""Shared fixtures of the Python package's tests. ctest runs them with PYTHONPATH=<build>/python
(the package in the build tree) and OCEAN_CLI=<the ocean tool> when the tool is built."""
import os
import subprocess

import pytest


@pytest.fixture
def cli_message():
    """The one-line message `ocean ARGS...` prints after "ocean: error: ", or None when the tool
    was not built (OCEAN_CLI unset)."""
    tool = os.environ.get("OCEAN_CLI")

    def run(*args):
        if not tool:
            return None
        r = subprocess.run([tool, *args], capture_output=True, text=True, check=False)
        assert r.returncode != 0, f"ocean {' '.join(args)} succeeded"
        lines = r.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("ocean: error: "), r.stderr
        return lines[0][len("ocean: error: "):]

    return run


@pytest.fixture
def small_preset():
    """A quick simulation: 32^2, two cascades, the moderate sea."""
    import ocean

    p = ocean.Preset("moderate")
    p.set("resolution=32")
    p.set("cascades_m=[200.0, 47.0]")
    return p
