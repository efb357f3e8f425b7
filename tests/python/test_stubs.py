"""The package's type stubs (ocean/_ocean.pyi, written from the extension's signatures when it is
built): they name every public function, class, method and property of the extension, and mypy
(Debian's) accepts correct use and reports misuse: a misspelt keyword, a wrong argument type."""
import ast
import inspect
import os
import subprocess
import sys

import pytest

import ocean

STUB = os.path.join(os.path.dirname(ocean.__file__), "_ocean.pyi")


def stub_tree():
    with open(STUB, encoding="utf-8") as f:
        return ast.parse(f.read())


def test_the_package_is_typed_and_the_stub_parses():
    assert os.path.isfile(os.path.join(os.path.dirname(ocean.__file__), "py.typed"))
    stub_tree()


def test_the_stub_names_every_public_member_of_the_extension():
    tree = stub_tree()
    functions = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
    classes = {n.name: {m.name for m in n.body if isinstance(m, ast.FunctionDef)}
               for n in tree.body if isinstance(n, ast.ClassDef)}
    variables = {n.target.id for n in tree.body if isinstance(n, ast.AnnAssign)}
    module = ocean._ocean
    for name in dir(module):
        if name.startswith("_") and name != "__version__":
            continue
        obj = getattr(module, name)
        if inspect.isclass(obj):
            assert name in classes, name
            for attr, member in vars(obj).items():
                if attr == "__init__" and "__init__(" not in (member.__doc__ or ""):
                    continue  # no constructor from Python (FrameView)
                if not attr.startswith("_") or attr == "__init__":
                    assert attr in classes[name], f"{name}.{attr}"
        elif callable(obj):
            assert name in functions, name
        elif name in ("__version__",) or isinstance(obj, (int, float, str)):
            assert name in variables, name
    # The keywords of each function are those the extension takes.
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            stub_keywords = [a.arg for a in node.args.args + node.args.kwonlyargs]
            doc = getattr(module, node.name).__wrapped__.__doc__ \
                if hasattr(getattr(module, node.name), "__wrapped__") \
                else getattr(module, node.name).__doc__
            first = doc.splitlines()[0]
            for keyword in stub_keywords:
                assert f"{keyword}:" in first, (node.name, keyword, first)
    assert "series" in classes["Simulator"]  # added by the pure-Python package


GOOD = """
import numpy as np
import ocean

s = ocean.spectrum("jonswap", omega=[0.5, 1.0], hs=2.0, tp=8.0)
peak: float = float(np.max(s))
sim = ocean.Simulator("moderate", threads=1)
sim.step(1.0)
t: float = sim.time
names = ocean.Preset.builtin_names()
first: str = names[0]
p = ocean.Preset("calm").set("resolution=32")
record = sim.series([[0.0, 0.0]], [1.0, 2.0])
q = p.updated({"foam.source": "ramp"}, seed=3)
same: bool = q == ocean.Preset.from_dict(q.to_dict())
speed = q["sea.wind_sea.wind_speed_mps"]
"""

BAD = """
import ocean

ocean.spectrum("jonswap", omega=[0.5], hss=2.0)
sim = ocean.Simulator("moderate")
sim.step("now")
"""


@pytest.fixture(scope="module")
def mypy_run(tmp_path_factory):
    """One mypy run (it takes tens of seconds) over a correct and a wrong use of the package."""
    tmp = tmp_path_factory.mktemp("mypy")
    (tmp / "good.py").write_text(GOOD)
    (tmp / "bad.py").write_text(BAD)
    env = dict(os.environ, MYPYPATH=os.path.dirname(os.path.dirname(ocean.__file__)))
    r = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir",
                        str(tmp / "cache"), str(tmp / "good.py"), str(tmp / "bad.py")],
                       capture_output=True, text=True, env=env, check=False)
    return r


def test_mypy_accepts_correct_use(mypy_run):
    assert "good.py" not in mypy_run.stdout, mypy_run.stdout + mypy_run.stderr


def test_mypy_reports_a_misspelt_keyword_and_a_wrong_type(mypy_run):
    r = mypy_run
    assert r.returncode == 1, r.stdout + r.stderr
    assert 'bad.py:4: error: Unexpected keyword argument "hss" for "spectrum"; did you mean ' \
        '"hs"?' in r.stdout, r.stdout
    assert 'bad.py:6: error: Argument 1 to "step" of "Simulator" has incompatible type "str"; ' \
        'expected "float"' in r.stdout, r.stdout
    assert "Found 2 errors in 1 file" in r.stdout, r.stdout
