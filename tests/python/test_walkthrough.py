"""docs/python.md's walk-through run as a notebook runs it: IPython (Debian's python3-ipython,
which ./dev installs) with its output history on, one top-level statement per cell, so that every
value a cell shows (arrays of the simulator's frames included) stays alive in Out while the
simulation steps on. No cell may fail, and no array the history holds may change afterwards."""
import ast
import os
import re

import numpy as np
import pytest

IPython = pytest.importorskip("IPython")

DOC = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")


def walkthrough_cells():
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    section = text.split("## Walk-through", 1)[1]
    block = re.search(r"```python\n(.*?)```", section, re.S)
    assert block, "docs/python.md: no ```python block under '## Walk-through'"
    code = block.group(1)
    return [ast.get_source_segment(code, node) for node in ast.parse(code).body]


def test_the_walkthrough_runs_in_ipython_with_its_output_history(tmp_path, monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell
    from traitlets.config import Config

    # IPython's profile and history in the test's own folder, not the user's home.
    monkeypatch.setenv("IPYTHONDIR", str(tmp_path))
    config = Config()
    config.HistoryManager.hist_file = str(tmp_path / "history.sqlite")
    shell = InteractiveShell.instance(config=config)
    try:
        seen = {}  # id → (the array in Out, a copy taken when it was shown)
        cells = walkthrough_cells()
        assert len(cells) >= 10
        for number, cell in enumerate(cells, 1):
            result = shell.run_cell(cell, store_history=True)
            assert result.success, f"cell {number} ({cell!r}) failed: {result.error_in_exec!r}"
            for value in shell.user_ns["Out"].values():
                if isinstance(value, np.ndarray) and id(value) not in seen:
                    seen[id(value)] = (value, value.copy())
        assert len(seen) >= 3, "the walk-through shows too few arrays to test the history"
        for value, copy in seen.values():
            assert np.array_equal(value, copy), "an array in Out changed after a later step"
        # The two heights shown are different frames (1 s apart), both still alive in Out.
        user = shell.user_ns
        assert not np.array_equal(user["f"]["height"], user["sim"].fields(0)["height"])
    finally:
        InteractiveShell.clear_instance()
