"""examples/python/heave_spectrum.py: the heave spectrum of a simulated sea agrees with the input
JONSWAP spectrum within sampling error.

Statistical tolerance (derived in the example's docstring): in each band the heave variance,
averaged over 8 seeds, has relative standard deviation sqrt(sum P_j^2) / sum P_j / sqrt(8) (P_j the
expected power of frequency bin j; each bin's power is exponentially distributed, two degrees of
freedom). A band passes when measured / expected - 1 is within 4 of those standard deviations
(a false alarm about once in 16 000 per band). The expectation on the patch's grid must equal the
integral of S over the band up to the grid's discretisation, 10 % (the 0.8-1.0 rad/s band, below
the peak, is resolved by the fewest wave vectors; the others agree to 3 %)."""
import importlib.util
import os

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def load_example():
    path = os.path.join(ROOT, "examples", "python", "heave_spectrum.py")
    spec = importlib.util.spec_from_file_location("heave_spectrum", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_heave_spectrum_agrees_with_the_input_spectrum():
    example = load_example()
    rows, _, _, _ = example.band_comparison(seeds=8)
    assert len(rows) == 4
    for r in rows:
        error = r["measured"] / r["expected"] - 1.0
        assert abs(error) < 4.0 * r["rel_std"], r
        assert r["expected"] == pytest.approx(r["input_integral"], rel=0.10), r
        assert r["dof"] > 100  # enough that the Gaussian bound above is meaningful
