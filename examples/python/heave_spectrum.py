"""Heave at a point of a simulated sea, and its spectrum against the input spectrum.

A notebook-style walk through what a naval architect does first with a wave model:

  1. a fetch-limited JONSWAP sea from wind speed and fetch (Hasselmann et al. 1973),
  2. a linear simulation of it (choppiness 0: the surface moves only up and down, so the heave of
     a point fixed in space is the surface height there, as linear theory has it),
  3. the heave time series at one point over one loop period, for several seeds,
  4. its spectrum (a periodogram) against the input S(omega), band by band.

The simulator quantises every frequency to a multiple of omega0 = 2 pi / T (T the loop period,
docs/math.md M.2.4), so over exactly one period the periodogram has no leakage: its bin j holds the
waves whose omega falls in [j omega0, (j + 1) omega0). The patch resolves the spectrum only between
its longest wave 2 pi / L and its Nyquist wavenumber pi N / L; the comparison uses that band.

Sampling error. At one point the heave of bin j is a sum of many wave components with random
phases: a complex Gaussian, whose power is exponentially distributed (two degrees of freedom).
With expected bin powers P_j (from the wave-vector spectrum on the patch's grid), the variance in
a band, averaged over S seeds, has relative standard deviation sqrt(sum P_j^2) / sum P_j / sqrt(S);
its degrees of freedom are 2 (sum P_j)^2 / sum P_j^2 per seed. The test (tests/python/
test_heave_example.py) accepts a band when the measured variance is within 4 standard deviations
of the expectation, and asks that the expectation on the grid agrees with the integral of S over
the band to within the grid's discretisation (a few per cent).

Run:  PYTHONPATH=build/release/python /usr/bin/python3 examples/python/heave_spectrum.py [out.png]
"""
import sys

import numpy as np

import ocean

# 1. The sea: 12 m/s over 60 km, JONSWAP with Hasselmann's mean gamma 3.3.
WIND_SPEED = 12.0  # U10, m/s
FETCH = 60e3  # m
# 2. The simulation: one 64 x 64 cascade of 600 m, looping after 600 s, heights only.
RESOLUTION = 64
PATCH = 600.0  # m
LOOP = 600.0  # s
DT = 0.5  # s: 1200 samples per period; Nyquist pi / DT = 6.3 rad/s above the grid's limit
POINT = (0.0, 0.0)  # world (x, z), m: a texel, where the height is the grid's value itself


def make_preset(seed):
    p = ocean.Preset()
    for assignment in (
            "sea.wind_sea.model=jonswap", f"sea.wind_sea.wind_speed_mps={WIND_SPEED}",
            f"sea.wind_sea.fetch_m={FETCH}", f"resolution={RESOLUTION}", f"cascades_m=[{PATCH}]",
            "choppiness=0", f"loop_period_s={LOOP}", f"seed={seed}"):
        p.set(assignment)
    return p


def heave_series(seed):
    """The heave at POINT over one loop period, sampled every DT."""
    sim = ocean.Simulator(make_preset(seed))
    times = np.arange(0.0, LOOP, DT)
    xz = np.array([POINT])
    heave = np.empty_like(times)
    for i, t in enumerate(times):
        sim.step(t)
        heave[i] = sim.heights(xz)[0]
    return heave


def periodogram(heave):
    """One-sided power per bin j (m^2), bin j at omega = j omega0, so that the powers add up to
    the variance of the series about its mean."""
    n = len(heave)
    x = np.fft.rfft(heave - heave.mean())
    power = 2.0 * np.abs(x) ** 2 / n**2
    if n % 2 == 0:
        power[-1] /= 2.0  # the Nyquist bin has no mirror image
    power[0] = 0.0
    return power


def expected_bin_power(sea, n_bins):
    """E[power] of each bin: the wave-vector spectrum F(k) dk^2 of every grid wave vector whose
    quantised frequency lands in the bin (docs/math.md M.6.2, M.2.4). The grid's Nyquist row and
    column and the DC term carry nothing (M.6.3)."""
    dk = 2.0 * np.pi / PATCH
    m = np.arange(RESOLUTION) - RESOLUTION // 2
    kx, kz = np.meshgrid(m * dk, m * dk)
    nyquist = (kx == m[0] * dk) | (kz == m[0] * dk)
    f = sea.wave_vector_spectrum(kx, kz) * dk**2
    f[nyquist] = 0.0
    k = np.hypot(kx, kz)
    omega = ocean.dispersion(k=np.where(k > 0, k, dk))["omega"]
    omega0 = 2.0 * np.pi / LOOP
    j = np.floor(omega / omega0 + 1e-9).astype(int)
    j[k == 0] = 0
    p = np.bincount(j.ravel(), weights=f.ravel(), minlength=n_bins)[:n_bins]
    p[0] = 0.0
    return p


def band_comparison(seeds=8, bands=((0.8, 1.0), (1.0, 1.2), (1.2, 1.45), (1.45, 1.75))):
    """Measured and expected heave variance in frequency bands [a, b) rad/s, averaged over
    `seeds` realisations, with the relative standard deviation of the measurement and the
    integral of the input S over the band. Returns a list of dicts and the averaged spectrum."""
    sea = ocean.SeaState(make_preset(1))
    n = int(round(LOOP / DT))
    omega0 = 2.0 * np.pi / LOOP
    measured = np.mean([periodogram(heave_series(s)) for s in range(1, seeds + 1)], axis=0)
    expected = expected_bin_power(sea, len(measured))
    bins = np.arange(len(measured)) * omega0
    rows = []
    for a, b in bands:
        sel = (bins >= a - 1e-9) & (bins < b - 1e-9)
        p = expected[sel]
        w = np.linspace(a, b, 2001)
        s = ocean.spectrum("jonswap", omega=w, wind_speed=WIND_SPEED, fetch=FETCH)
        rows.append(dict(band=(a, b), measured=measured[sel].sum(), expected=p.sum(),
                         rel_std=np.sqrt((p**2).sum() / seeds) / p.sum(),
                         dof=2.0 * p.sum() ** 2 / (p**2).sum() * seeds,
                         input_integral=np.trapz(s, w)))
    return rows, bins, measured / omega0, n


def main(argv):
    rows, omega, s_measured, _ = band_comparison()
    print(f"{'band, rad/s':>14} {'measured m^2':>13} {'expected':>10} {'rel. std':>9} "
          f"{'dof':>6} {'int S dw':>10}")
    for r in rows:
        print(f"{r['band'][0]:6.2f}-{r['band'][1]:<6.2f} {r['measured']:13.5f} "
              f"{r['expected']:10.5f} {r['rel_std']:9.3f} {r['dof']:6.0f} "
              f"{r['input_integral']:10.5f}")
    if len(argv) > 1:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        w = np.linspace(0.05, 3.0, 600)
        fig, ax = plt.subplots(figsize=(9, 5))
        # The periodogram smoothed over 9 bins, for the eye.
        ax.plot(omega, np.convolve(s_measured, np.ones(9) / 9, "same"), label="heave (8 seeds)")
        ax.plot(w, ocean.spectrum("jonswap", omega=w, wind_speed=WIND_SPEED, fetch=FETCH),
                "k", label=f"JONSWAP, U10 = {WIND_SPEED:g} m/s, F = {FETCH / 1e3:g} km")
        ax.set(xlabel="ω, rad/s", ylabel="S, m²·s/rad", xlim=(0, 3), title="Heave spectrum")
        ax.legend()
        fig.savefig(argv[1], dpi=100)
        print(f"wrote {argv[1]}")


if __name__ == "__main__":
    main(sys.argv)
