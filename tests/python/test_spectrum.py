"""ocean.spectrum, spectrum_info, dispersion, spreading, depth_factor and SeaState against the
published values the C++ tests use (tests/spectrum/*_test.cpp cite each source, commit and line)."""
import math

import numpy as np
import pytest

import ocean


def test_jonswap_xdyn_values():
    # xdyn @4c4db1c JonswapSpectrumTest.cpp lines 34-50 (tests/spectrum/jonswap_test.cpp).
    omega = np.array([0.4, 0.5, 0.6, 0.7, 0.8])
    expected = [0.001548977510098, 0.046145520023689, 0.241661465488933, 0.144435240716521,
                0.061449169843241]
    s = ocean.spectrum("jonswap", omega=omega, hs=1.0, tp=10.0, gamma=3.3)
    np.testing.assert_allclose(s, expected, rtol=0, atol=1e-14)


def test_jonswap_wafo_gamma_one():
    # WAFO test_models.py lines 21-29: Jonswap(Hm0 = 7, Tp = 11, gamma = 1) at omega = 1, 2, 3.
    s = ocean.spectrum("jonswap", omega=[1.0, 2.0, 3.0], hs=7.0, tp=11.0, gamma=1.0)
    np.testing.assert_allclose(s, [1.42694133, 0.05051648, 0.00669692], rtol=0, atol=6e-9)


def test_bretschneider_xdyn_values():
    # xdyn BretschneiderSpectrumTest.cpp lines 30-39 (tests/spectrum/pierson_moskowitz_test.cpp).
    for hs, tp, w, expected in ((1.0, 5.0, 1.0, 0.034510725921325),
                                (2.0, 5.0, 1.0, 0.138042903685298),
                                (2.0, 5.0, 10.0, 0.000031161194389),
                                (2.0, 10.0, 0.5, 0.276085807370596)):
        s = ocean.spectrum("pierson-moskowitz", omega=[w], hs=hs, tp=tp)
        assert s[0] == pytest.approx(expected, abs=1e-14)


def test_tma_wafo_values():
    # WAFO test_models.py lines 31-35: Tmaspec(Hm0 = 7, Tp = 11, gamma = 1, h = 10).
    s = ocean.spectrum("tma", omega=[1.0, 2.0, 3.0], hs=7.0, tp=11.0, gamma=1.0, depth=10.0)
    np.testing.assert_allclose(s, [0.70106233, 0.05022433, 0.00669692], rtol=0, atol=6e-9)


def test_depth_factor_wafo_values():
    # WAFO phi1 (tests/spectrum/tma_test.cpp WafoExactFactor).
    assert ocean.depth_factor([1.0], depth=30.0)[0] == pytest.approx(0.9659327465, abs=1e-9)
    np.testing.assert_allclose(ocean.depth_factor(np.array([1.0, 2.0]), depth=10.0),
                               [0.49130424, 0.99421674], rtol=0, atol=2e-7)
    # Thompson & Vincent (1983): omega_h^2 / 2 below 1, 1 - (2 - omega_h)^2 / 2 up to 2.
    wh = np.array([0.5, 1.0, 1.5, 2.0])
    tv = ocean.depth_factor(wh * math.sqrt(9.81 / 10.0), depth=10.0, method="thompson-vincent")
    np.testing.assert_allclose(tv, [0.125, 0.5, 0.875, 1.0], atol=1e-12)


def test_spectrum_keeps_the_shape_of_omega():
    omega = np.linspace(0.5, 2.0, 12).reshape(3, 4)
    s = ocean.spectrum("jonswap", omega=omega, hs=1.0, tp=10.0, gamma=3.3)
    assert s.shape == (3, 4)
    flat = ocean.spectrum("jonswap", omega=omega.ravel(), hs=1.0, tp=10.0, gamma=3.3)
    np.testing.assert_array_equal(s.ravel(), flat)


def test_spectrum_info_dnv_gamma_and_hs():
    # DNV-RP-C205 3.5.5.5: gamma = 5 for Tp / sqrt(Hs) <= 3.6 (Hs 3.5, Tp 5.5: 2.94); the exact
    # normalisation makes 4 sqrt(m0) the requested Hs.
    info = ocean.spectrum_info("jonswap", hs=3.5, tp=5.5, gamma="auto", normalization="exact")
    assert info["gamma"] == 5.0
    assert info["hs_m"] == pytest.approx(3.5, rel=1e-6)
    assert info["peak_period_s"] == pytest.approx(5.5, rel=1e-12)


def test_pierson_moskowitz_wind_hs_closed_form():
    # Pierson & Moskowitz (1964): Hs = 0.2093 U19.5^2 / g (docs/math.md M.3.2: 4 sqrt(alpha/(4 beta))).
    info = ocean.spectrum_info("pierson-moskowitz", wind_speed=15.0)
    assert info["hs_m"] == pytest.approx(4 * math.sqrt(0.0081 / (4 * 0.74)) * 15.0**2 / 9.81,
                                         rel=1e-7)


def test_dispersion_wafo_values():
    # WAFO test_dispersion_relation.py lines 11-53 (tests/spectrum/dispersion_test.cpp).
    deep = ocean.dispersion(omega=[1.0, 2.0, 3.0])
    np.testing.assert_allclose(deep["k"], [0.1019368, 0.4077472, 0.91743119], rtol=1e-7)
    h20 = ocean.dispersion(omega=[1.0, 2.0, 3.0], depth=20.0)
    np.testing.assert_allclose(h20["k"], [0.10503601, 0.40774726, 0.91743119], rtol=1e-7)
    w = ocean.dispersion(k=[0.01, 0.21, 0.41], depth=20.0)["omega"]
    np.testing.assert_allclose(w, [0.13914927, 1.43498213, 2.00551724], rtol=1e-7)


def test_dispersion_mhkit_values_and_identities():
    # MHKiT-Python @9fa9f9c ValData1.json, h = 10 m.
    d = ocean.dispersion(k=[1.0, 1 / 6, 1 / 11], depth=10.0)
    np.testing.assert_allclose(d["omega"], [3.132092073927611, 1.23384124328053,
                                            0.8017041035494386], rtol=2e-7)
    # Deep water: c_g = c / 2 and wavelength 2 pi / k.
    deep = ocean.dispersion(k=np.array([0.05, 0.3, 2.0]))
    np.testing.assert_allclose(deep["group_velocity"], deep["phase_velocity"] / 2, rtol=1e-14)
    np.testing.assert_allclose(deep["wavelength_m"], 2 * np.pi / np.array([0.05, 0.3, 2.0]))


def test_cos2s_xdyn_and_wafo_values():
    # xdyn Cos2sDirectionalSpreadingTest.cpp lines 34-57: psi0 = pi/4, s = 3, psi = pi/3.
    d = ocean.spreading([math.pi / 3 - math.pi / 4], model="cos2s", s=3.0)
    assert d[0] == pytest.approx(8 * math.cos(math.pi / 24) ** 6 / (5 * math.pi), abs=1e-15)
    # WAFO test_models.py lines 73-128: s = 15 at theta = 2 pi i / 49.
    i = np.array([0, 1, 2, 3, 4, 6, 10, 24])
    expected = [1.10168934, 1.03576796, 0.860302298, 0.630309013, 0.406280137, 0.113052757,
                0.00143800617, 1.65021852e-45]
    np.testing.assert_allclose(ocean.spreading(2 * np.pi * i / 49, model="cos2s", s=15.0),
                               expected, rtol=1e-8)


def test_spreading_power_cosine_rules_and_normalisation():
    # Aebi, VR Ocean, eqs. 6-8: s(1) = 6, counter-wave energy sigma(1) = 0.01.
    d = ocean.spreading([0.0, math.pi], model="power-cosine")
    assert d[1] / d[0] == pytest.approx(0.01, abs=1e-12)
    # Every model integrates to 1 over (-pi, pi].
    theta = np.linspace(-np.pi, np.pi, 20001)
    for model in ("power-cosine", "donelan-banner", "mitsuyasu", "hasselmann"):
        d = ocean.spreading(theta, model=model, wind_speed=10.0, fetch=1e5)
        assert np.trapz(d, theta) == pytest.approx(1.0, abs=1e-5), model


def test_sea_state_variance_is_the_spectrum_moment():
    sea = ocean.SeaState("moderate")
    m0 = ocean.spectrum_info("jonswap", wind_speed=10.0, fetch=100e3)["m0"]
    assert sea.variance_m2 == pytest.approx(m0, rel=1e-12)
    assert sea.systems[0]["model"] == "jonswap"
    # F(k) dk^2 summed over a fine grid is m0 (docs/math.md M.5.1).
    k = np.linspace(-1.0, 1.0, 801)
    kx, kz = np.meshgrid(k, k)
    f = sea.wave_vector_spectrum(kx, kz)
    assert f.sum() * (k[1] - k[0]) ** 2 == pytest.approx(m0, rel=0.02)


def test_spectrum_in_hertz_keeps_the_variance_and_peaks_at_one_over_tp():
    """S(f) = 2π·S(ω = 2πf): the same variance m0 = ∫S(f) df = (Hs/4)² and the peak at 1/Tp."""
    hs, tp = 3.0, 10.0
    f = np.linspace(1e-4, 3.0, 300001)
    s = ocean.spectrum_hz("pierson-moskowitz", f, hs=hs, tp=tp)
    assert s.shape == f.shape
    m0 = np.trapz(s, f)
    assert 4.0 * math.sqrt(m0) == pytest.approx(hs, rel=2e-3)
    assert f[np.argmax(s)] == pytest.approx(1.0 / tp, abs=2e-5)
    f0 = np.array([[0.08, 0.1], [0.2, 0.5]])
    np.testing.assert_allclose(
        ocean.spectrum_hz("jonswap", f0, hs=hs, tp=tp),
        2.0 * math.pi * ocean.spectrum("jonswap", omega=2.0 * math.pi * f0, hs=hs, tp=tp),
        rtol=1e-15)
    with pytest.raises(ValueError, match="f must be finite and >= 0"):
        ocean.spectrum_hz("pierson-moskowitz", [-0.1], hs=hs, tp=tp)
