"""ocean.figures: the sea-state and map figures as functions and as `python3 -m ocean.figures`."""
import os
import subprocess
import sys

import numpy as np
import pytest

import ocean
import ocean.figures

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def test_sea_state_figure_panels():
    fig = ocean.figures.sea_state_figure("jonswap", wind_speed=15.0, fetch=200e3)
    axes = fig.get_axes()
    assert len(axes) == 4
    # The chosen spectrum is drawn from ocean.spectrum itself (the black curve, last line).
    line = axes[0].get_lines()[-1]
    w, s = line.get_data()
    np.testing.assert_array_equal(s, ocean.spectrum("jonswap", omega=w, wind_speed=15.0,
                                                    fetch=200e3))
    # Four dispersion curves: deep water and 50, 10, 3 m; shallower water has shorter waves.
    lengths = [ln.get_ydata()[-1] for ln in axes[3].get_lines()]
    assert len(lengths) == 4 and lengths == sorted(lengths, reverse=True)


def test_maps_figure_of_a_frame(small_preset):
    sim = ocean.Simulator(small_preset)
    sim.step(2.0)
    fig = ocean.figures.maps_figure(sim, cascade=0)
    images = [a.get_images()[0].get_array() for a in fig.get_axes() if a.get_images()]
    assert len(images) == 3
    np.testing.assert_array_equal(images[0], sim.fields(0)["height"])
    sim.step(3.0)  # the figure kept copies, no view
    sim.step(4.0)


@pytest.mark.parametrize("args", [["sea-state", "--hs", "3", "--tp", "9"],
                                  ["maps", "--preset", "calm", "--set", "resolution=32"]])
def test_command_line_writes_a_png(tmp_path, args):
    out = tmp_path / "figure.png"
    r = subprocess.run([sys.executable, "-m", "ocean.figures", *args, "-o", str(out)],
                       capture_output=True, text=True, env=os.environ, check=False)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes()[:8] == PNG_SIGNATURE


def test_command_line_bad_input_is_one_line(tmp_path):
    r = subprocess.run([sys.executable, "-m", "ocean.figures", "sea-state", "--hs", "-1",
                        "--tp", "9", "-o", str(tmp_path / "x.png")],
                       capture_output=True, text=True, env=os.environ, check=False)
    assert r.returncode == 2
    assert r.stderr == "ocean.figures: error: hs = -1 is out of range: must be in [1e-06, 50]\n"
    assert not (tmp_path / "x.png").exists()
