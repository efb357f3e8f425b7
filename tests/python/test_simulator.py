"""ocean.Simulator: field views (no copy, read-only, tied to the simulator and to their frame),
step / kick / wait, and batched height queries against exact identities."""
import gc
import threading

import numpy as np
import pytest

import ocean


def test_fields_are_read_only_views_of_one_frame(small_preset):
    sim = ocean.Simulator(small_preset)
    sim.step(1.0)
    f = sim.fields(0)
    n = sim.resolution
    assert f["displacement"].shape == (n, n, 3) and f["displacement"].dtype == np.float32
    assert f["height"].shape == (n, n)
    # height is the h column of the displacement itself, not a copy.
    assert np.shares_memory(f["height"], f["displacement"])
    np.testing.assert_array_equal(f["height"], f["displacement"][..., 1])
    assert isinstance(f["height"].base, ocean.FrameView)
    assert not f["displacement"].flags.writeable
    with pytest.raises(ValueError):
        f["height"][0, 0] = 1.0
    # The half-precision copy the renderer uploads carries the same heights.
    np.testing.assert_allclose(f["displacement_half"][..., 1].astype(np.float32), f["height"],
                               rtol=1e-3, atol=1e-4)
    # Unit normals; Jacobian of a flat surface would be 1: here it varies around it.
    np.testing.assert_allclose(np.linalg.norm(f["normal"], axis=-1), 1.0, atol=1e-5)
    assert f["jacobian"].shape == (n, n) and f["foam"].shape == (n, n)
    assert f["packed"].shape == (n, n, 4) and f["packed"].dtype == np.uint8


def test_a_step_never_overwrites_a_viewed_frame(small_preset):
    sim = ocean.Simulator(small_preset)
    sim.step(1.0)
    old = sim.fields(0)["height"]
    kept = np.array(old)
    for t in (2.0, 3.0, 4.0):  # the second step writes the buffer `old` shows: it goes to `old`
        sim.step(t)
        np.testing.assert_array_equal(old, kept)
    sim.kick(5.0)
    sim.wait()
    np.testing.assert_array_equal(old, kept)
    assert sim.time == 5.0
    # The simulation is the same as one whose frames nobody held.
    plain = ocean.Simulator(small_preset)
    plain.step(4.0)
    plain.step(5.0)
    np.testing.assert_array_equal(sim.fields(0)["displacement"], plain.fields(0)["displacement"])
    np.testing.assert_array_equal(sim.fields(1)["foam"], plain.fields(1)["foam"])


def test_held_frames_through_a_notebook_session(small_preset):
    """What a notebook does: every step's arrays stay referenced (the output history, a list),
    and stepping goes on; each held array keeps its own frame's data."""
    sim = ocean.Simulator(small_preset)
    history = []
    for i in range(8):
        sim.step(0.5 * i)
        f = sim.fields(i % 2)
        history.append((0.5 * i, i % 2, f["height"], f["packed"], sim.frame_index))
    assert [h[4] for h in history] == list(range(1, 9))  # one count, not one per buffer
    reference = ocean.Simulator(small_preset)
    for t, cascade, height, packed, _ in history:
        reference.step(t)
        r = reference.fields(cascade)
        np.testing.assert_array_equal(height, r["height"])
        np.testing.assert_array_equal(packed, r["packed"])
        del r
    # reconfigure with views alive: they keep their frames, the simulator starts afresh.
    held = sim.fields(0)["displacement"]
    kept = np.array(held)
    sim.reconfigure(small_preset)
    sim.step(1.0)
    sim.step(2.0)
    np.testing.assert_array_equal(held, kept)
    assert sim.frame_index == 2


def test_a_view_keeps_the_simulator_alive(small_preset):
    sim = ocean.Simulator(small_preset)
    sim.step(4.0)
    h = sim.fields(1)["height"]
    kept = np.array(h)
    del sim
    gc.collect()
    for _ in range(3):  # allocations that would reuse freed frame memory
        ocean.Simulator(small_preset).step(9.0)
    np.testing.assert_array_equal(h, kept)


def test_kick_wait_equals_step(small_preset):
    a = ocean.Simulator(small_preset)
    b = ocean.Simulator(small_preset)
    a.step(2.5)
    b.kick(2.5)
    b.wait()
    assert b.time == 2.5
    np.testing.assert_array_equal(a.fields(0)["displacement"], b.fields(0)["displacement"])


def test_heights_at_displaced_texels_are_their_heights(small_preset):
    # A texel starting at p lands at p + D_xz(p) with height h(p) (docs/math.md M.7.6-M.7.7):
    # the query at the landing point returns h(p), summed over cascades. With one cascade the
    # sum is the texel's own value.
    p = ocean.Preset("moderate")
    p.set("resolution=32")
    p.set("cascades_m=[100.0]")
    sim = ocean.Simulator(p)
    sim.step(3.0)
    d = np.array(sim.fields(0)["displacement"], dtype=np.float64)
    size = sim.patch_sizes[0]
    rows, cols = np.mgrid[0:32:5, 0:32:5]
    start = np.stack([cols.ravel(), rows.ravel()], axis=1) * size / 32
    disp = d[rows.ravel(), cols.ravel()]
    xz = start + disp[:, [0, 2]]
    r = sim.heights(xz, full=True)
    np.testing.assert_allclose(r["height"], disp[:, 1], atol=1e-4)
    np.testing.assert_allclose(np.mod(r["source_xz"] - start + size / 2, size) - size / 2, 0,
                               atol=1e-3)
    assert r["displacement"].shape == (len(xz), 3) and r["iterations"].min() >= 1


def test_displacements_at_texels_are_the_cascades_summed(small_preset):
    # M.7.6: texel (col, row) of cascade c starts at (col, row)·L_c/N and bilinear sampling at a
    # texel is the texel's own value, so where texel (0, 0) of both patches (200 m and 47 m)
    # starts, at the origin and at multiples of 9400 m = 200·47 m, D is the plain sum of the two
    # texels; between texels it is the bilinear blend, at a cell's centre the mean of its corners.
    sim = ocean.Simulator(small_preset)
    sim.step(2.0)
    maps = [np.array(sim.fields(c)["displacement"], dtype=np.float64) for c in range(2)]
    corners = np.array([[0.0, 0.0], [9400.0, -18800.0]])
    np.testing.assert_allclose(sim.displacements(corners),
                               np.tile(maps[0][0, 0] + maps[1][0, 0], (2, 1)), rtol=0, atol=1e-9)
    one = ocean.Simulator(ocean.Preset("moderate").updated(resolution=32, cascades_m=[100.0]))
    one.step(2.0)
    d = np.array(one.fields(0)["displacement"], dtype=np.float64)
    cell = 100.0 / 32
    centre = np.array([[(5 + 0.5) * cell, (7 + 0.5) * cell]])  # between cols 5-6, rows 7-8
    mean = (d[7, 5] + d[7, 6] + d[8, 5] + d[8, 6]) / 4
    np.testing.assert_allclose(one.displacements(centre)[0], mean, rtol=0, atol=1e-12)


def test_displaced_points_have_their_heights_and_surface(small_preset):
    # A point starting at p lands at p + D_xz(p) with height h(p) (M.7.7); surface() returns the
    # same height as heights() and the normal normalize(−∂η/∂x, 1, −∂η/∂z) (M.7.11), checked by
    # central differences of heights() over ±1 mm. The field is bilinear in each cell, so its
    # slope jumps at cell edges: points whose source lies within 5 mm of an edge of either
    # cascade (where the differences straddle two cells) are left out, about 2 % of them.
    # Elsewhere the differences err by the third derivative times δ²/6 and by the inverse's
    # residual over 2δ: heights() meets h(p) to 1.5e-7 m on these points (Newton ends well inside
    # its 1e-6 m stop), 7.5e-5 over 2 mm; 2e-4 bounds both (3.6e-5 seen).
    sim = ocean.Simulator(small_preset)
    sim.step(4.0)
    start = np.random.default_rng(3).uniform(-300, 300, size=(200, 2))
    d = sim.displacements(start)
    landed = start + d[:, [0, 2]]
    np.testing.assert_allclose(sim.heights(landed), d[:, 1], rtol=0, atol=1e-6)
    s = sim.surface(landed)
    np.testing.assert_array_equal(s["height"], sim.heights(landed))
    np.testing.assert_allclose(np.linalg.norm(s["normal"], axis=1), 1.0, atol=1e-12)
    delta = 1e-3
    margin = [np.abs((start / cell + 0.5) % 1 - 0.5) * cell
              for cell in np.array(sim.patch_sizes) / sim.resolution]
    inside = np.all(np.min(margin, axis=0) > 5 * delta, axis=1)
    assert inside.sum() > 150
    start, landed, s = start[inside], landed[inside], {k: v[inside] for k, v in s.items()}
    dx = (sim.heights(landed + [delta, 0]) - sim.heights(landed - [delta, 0])) / (2 * delta)
    dz = (sim.heights(landed + [0, delta]) - sim.heights(landed - [0, delta])) / (2 * delta)
    expected = np.column_stack([-dx, np.ones(len(dx)), -dz])
    expected /= np.linalg.norm(expected, axis=1)[:, None]
    np.testing.assert_allclose(s["normal"], expected, rtol=0, atol=2e-4)
    assert np.isnan(s["velocity"]).all()  # the preset's outputs carry no velocity


def test_foam_weights_are_shares_of_the_slope_variance(small_preset):
    # The breaking source weighs each cascade by its share of the bands' slope variance
    # (docs/rendering.md R.11): positive shares summing to one. The ramp source unites instead.
    w = ocean.Simulator(small_preset).foam_weights
    assert len(w) == 2 and min(w) > 0 and sum(w) == pytest.approx(1.0, abs=1e-12)
    ramp = small_preset.updated({"foam.source": "ramp"})
    assert ocean.Simulator(ramp).foam_weights == []


@pytest.mark.parametrize("method", ["displacements", "surface"])
def test_point_queries_refuse_bad_points(small_preset, method):
    sim = ocean.Simulator(small_preset)
    with pytest.raises(ValueError, match=r"xz must be an \(n, 2\) array .* got shape \(3\)"):
        getattr(sim, method)(np.zeros(3))
    with pytest.raises(ValueError, match="x"):
        getattr(sim, method)(np.array([[np.nan, 0.0]]))


def test_heights_from_threads_agree(small_preset):
    # The GIL is released during a query: several threads query at once and get the same values.
    sim = ocean.Simulator(small_preset)
    sim.step(5.0)
    xz = np.random.default_rng(1).uniform(-500, 500, size=(20000, 2))
    expected = sim.heights(xz)
    results = [None] * 4

    def work(i):
        results[i] = sim.heights(xz)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, expected)


def test_surface_statistics_match_the_spectrum():
    # The measured Hs of the simulated surface against the spectrum's expectation on the grid,
    # within 4 standard deviations of sampling (ocean/statistics.hpp hs_sampling_rel_std).
    p = ocean.Preset("moderate")
    p.set("resolution=64")
    p.set("cascades_m=[400.0]")
    s = ocean.surface_stats(p, seeds=4)
    assert s["seeds"] == 4 and s["resolution"] == 64
    assert abs(s["hs_measured_m"] / s["hs_spectrum_m"] - 1) < 4 * s["hs_sampling_rel_std"]


def test_series_is_a_wave_gauge_record_of_step_and_heights(small_preset):
    """series(points, times) steps to each time and queries the points: the same numbers as
    step(t) and heights(xz) called in turn on a twin simulator, rows by time, columns by point."""
    points = np.array([[0.0, 0.0], [13.5, -7.25], [120.0, 40.0]])
    times = np.array([0.0, 0.25, 0.5, 1.75, 3.0])
    sim = ocean.Simulator(small_preset)
    record = sim.series(points, times)
    assert record.shape == (times.size, points.shape[0])
    assert sim.time == times[-1]
    twin = ocean.Simulator(small_preset)
    for i, t in enumerate(times):
        twin.step(float(t))
        np.testing.assert_array_equal(record[i], twin.heights(points))
    # A sea: the record moves, about the mean level (Hs of the moderate sea is metres).
    assert np.ptp(record) > 0.05
    assert np.all(np.abs(record) < 10.0)


def test_series_as_xarray_carries_times_and_positions(small_preset):
    import xarray  # Debian's python3-xarray, installed by ./dev
    points = [[1.0, 2.0], [3.0, 4.0]]
    times = [0.5, 1.0, 1.5]
    da = ocean.Simulator(small_preset).series(points, times, as_xarray=True)
    assert isinstance(da, xarray.DataArray)
    assert da.dims == ("time", "point")
    np.testing.assert_array_equal(da["time"].values, times)
    np.testing.assert_array_equal(da["x"].values, [1.0, 3.0])
    np.testing.assert_array_equal(da["z"].values, [2.0, 4.0])
    assert da.attrs["units"] == "m"
    np.testing.assert_array_equal(da.values, ocean.Simulator(small_preset).series(points, times))


@pytest.mark.parametrize("points, times, match", [
    ([1.0, 2.0], [0.0], "points must be an \\(n, 2\\) array"),
    ([[1.0, 2.0]], [], "times must be a non-empty 1-D array"),
    ([[1.0, 2.0]], [[0.0]], "times must be a non-empty 1-D array"),
    ([[1.0, 2.0]], [float("nan")], "times must be finite and >= 0"),
    ([[1.0, 2.0]], [-1.0], "times must be finite and >= 0"),
    ([[float("inf"), 2.0]], [0.0], "points must be finite"),
])
def test_series_refuses_bad_input_before_stepping(small_preset, points, times, match):
    sim = ocean.Simulator(small_preset)
    sim.step(2.0)
    with pytest.raises(ValueError, match=match):
        sim.series(points, times)
    assert sim.time == 2.0
