"""Shared fixtures of the Python package's tests. ctest runs them with PYTHONPATH=<build>/python
(the package in the build tree) and OCEAN_CLI=<the ocean tool> when the tool is built."""
import os
import re
import subprocess

import pytest


def python_names(message):
    """The tool's message in Python's names: each flag as its keyword ("--wind-speed" is
    "wind_speed"), with its placeholder as an assignment ("--fetch M" is "fetch=M")."""
    message = re.sub(r"(?<![\w-])--([a-z][\w-]*) (?=[A-Z][A-Z0-9]*(?:[ ,):]|$))",
                     lambda m: m.group(1).replace("-", "_") + "=", message)
    return re.sub(r"(?<![\w-])--([a-z][\w-]*)", lambda m: m.group(1).replace("-", "_"), message)


@pytest.fixture
def cli_message():
    """The one-line message `ocean ARGS...` prints after "ocean: error: ", in Python's names
    (python_names), or None when the tool was not built (OCEAN_CLI unset)."""
    tool = os.environ.get("OCEAN_CLI")

    def run(*args):
        if not tool:
            return None
        r = subprocess.run([tool, *args], capture_output=True, text=True, check=False)
        assert r.returncode != 0, f"ocean {' '.join(args)} succeeded"
        lines = r.stderr.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("ocean: error: "), r.stderr
        return python_names(lines[0][len("ocean: error: "):])

    return run


def make_preset(name, *assignments):
    """A built-in preset with key=value overrides."""
    import ocean

    p = ocean.Preset(name)
    for a in assignments:
        p.set(a)
    return p


@pytest.fixture
def small_preset():
    """A quick simulation: 32^2, two cascades, the moderate sea."""
    return make_preset("moderate", "resolution=32", "cascades_m=[200.0, 47.0]")


@pytest.fixture
def storm_16():
    """The storm on 16^2 cascades of 300 and 71 m: the smallest bake worth comparing."""
    return make_preset("storm", "resolution=16", "cascades_m=[300.0, 71.0]")
