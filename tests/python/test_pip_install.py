"""`pip install .` (pyproject.toml, bindings/python/tools/ocean_build.py) into a venv made with
--system-site-packages, as a user would, with no package index (--no-index): the backend reuses
the build folder the tests run from (OCEAN_BUILD_DIR), so nothing is compiled again. The
installed package is the venv's, carries the project's version, its stubs and py.typed, computes
the same heights as the build tree's, and pip uninstalls it whole. A build folder that is not one
fails with one line naming it."""
import os
import subprocess
import sys
import venv

import pytest

import ocean

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(ocean.__file__))))


def clean_env(**extra):
    """The environment without the build tree's package on the path and without the machine's pip
    configuration or cache: the same install on every machine, nothing written to the home."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH" and not k.startswith("PIP_")}
    env.update(PIP_CONFIG_FILE=os.devnull, PIP_NO_CACHE_DIR="1")
    env.update(extra)
    return env


@pytest.fixture(scope="module")
def environment(tmp_path_factory):
    where = tmp_path_factory.mktemp("venv")
    venv.EnvBuilder(system_site_packages=True, with_pip=True).create(where)
    return where


def run(environment, *args, env=None, cwd=None):
    return subprocess.run([os.path.join(environment, "bin", "python"), *args],
                          capture_output=True, text=True, check=False, cwd=cwd,
                          env=env if env is not None else clean_env())


HEIGHTS = """
import json, sys
import numpy as np
import ocean
p = ocean.Preset("moderate")
p.set("resolution=32")
sim = ocean.Simulator(p)
sim.step(3.0)
h = sim.heights(np.array([[0.0, 0.0], [10.5, -3.25], [123.0, 77.0]]))
print(json.dumps({"file": ocean.__file__, "version": ocean.__version__,
                  "heights": [float(x) for x in h]}))
"""


def test_pip_installs_the_package_into_a_venv(environment, tmp_path):
    r = run(environment, "-m", "pip", "install", "--no-index", ROOT,
            env=clean_env(OCEAN_BUILD_DIR=BUILD))
    assert r.returncode == 0, r.stdout + r.stderr
    shown = run(environment, "-m", "pip", "show", "ocean")
    assert shown.returncode == 0 and f"Version: {ocean.__version__}" in shown.stdout, shown.stdout
    import json

    out = run(environment, "-c", HEIGHTS, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    got = json.loads(out.stdout)
    assert got["file"].startswith(str(environment)), got["file"]
    assert got["version"] == ocean.__version__
    installed = os.path.dirname(got["file"])
    for name in ("py.typed", "_ocean.pyi", "figures.py", "shards.py"):
        assert os.path.isfile(os.path.join(installed, name)), name
    # The same computation in the build tree's package gives the same doubles.
    here = subprocess.run([sys.executable, "-c", HEIGHTS], capture_output=True, text=True,
                          check=True, cwd=tmp_path)
    assert json.loads(here.stdout)["heights"] == got["heights"]
    removed = run(environment, "-m", "pip", "uninstall", "-y", "ocean")
    assert removed.returncode == 0, removed.stderr
    assert not os.path.exists(installed)


def test_a_build_folder_that_is_not_one_is_named(environment, tmp_path):
    r = run(environment, "-m", "pip", "install", "--no-index", ROOT,
            env=clean_env(OCEAN_BUILD_DIR=str(tmp_path)))
    assert r.returncode != 0
    assert f"OCEAN_BUILD_DIR = '{tmp_path}' is not a configured build folder" in r.stdout + r.stderr
