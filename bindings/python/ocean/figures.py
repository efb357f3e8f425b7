"""Figures of a sea state and of a simulated frame, drawn with matplotlib.

    sea_state_figure(**sea)      spectra, spreading, TMA depth factor, dispersion (2x2), as
                                 `ocean spectrum --plot` draws them
    maps_figure(simulator)       height, slope and foam maps of one cascade of the published frame

Both return a matplotlib Figure; the command line writes PNG files with the Agg backend:

    python3 -m ocean.figures sea-state --wind-speed 15 --fetch 200000 -o sea.png
    python3 -m ocean.figures maps --preset storm --time 10 -o maps.png
"""
import argparse
import sys

import numpy as np

import ocean

_OTHER_MODELS = ("pierson-moskowitz", "jonswap", "tma", "phillips")


def _comparison(model, sea):
    """The sea keywords for another spectrum family of the same sea, or None when it has none."""
    hs_form = sea.get("hs") is not None
    if hs_form and model == "phillips":
        return None
    q = dict(sea)
    jonswap_family = model in ("jonswap", "tma")
    if model == "tma":
        q["depth"] = sea.get("depth") or 10.0
    else:
        q.pop("depth", None)
    if not hs_form and jonswap_family and q.get("fetch") is None:
        q["fetch"] = ocean._ocean.DEFAULT_FETCH_M
    if not jonswap_family:
        q.pop("fetch", None)
        q.pop("gamma", None)
    if model != "phillips":
        q.pop("phillips_amplitude", None)
        q.pop("cutoff_length", None)
    return q


def sea_state_figure(model="jonswap", **sea):
    """The sea-state figure for ocean.spectrum's keywords: S(omega) of the chosen model beside the
    other families for the same wind or Hs/Tp; the five spreading functions at the peak; TMA's
    depth factor (exact and Thompson-Vincent); wavelength against period for several depths."""
    import matplotlib.figure

    sea = {k: v for k, v in sea.items() if v is not None}
    info = ocean.spectrum_info(model, **sea)
    wp = info["peak_omega"]
    fig = matplotlib.figure.Figure(figsize=(12, 8), layout="constrained")
    fig.suptitle(f"Sea state: {model}  —  Hs = {info['hs_m']:.2f} m, "
                 f"Tp = {info['peak_period_s']:.2f} s")
    ax = fig.subplots(2, 2)

    omega = np.linspace(0.02 * wp, 4.0 * wp, 600)
    for other in _OTHER_MODELS:
        q = None if other == model else _comparison(other, sea)
        if q is None:
            continue
        try:
            ax[0, 0].plot(omega, ocean.spectrum(other, omega=omega, **q), "--", label=other)
        except ValueError:
            pass  # a comparison that does not apply to this sea state is left out
    ax[0, 0].plot(omega, ocean.spectrum(model, omega=omega, **sea), "k", lw=2,
                  label=f"{model} (Hs {info['hs_m']:.2f} m)")
    ax[0, 0].set(title="Frequency spectra S(ω)", xlabel="ω, rad/s", ylabel="S, m²·s/rad",
                 xlim=(0, None), ylim=(0, None))
    ax[0, 0].legend()

    degrees = np.linspace(-180.0, 180.0, 721)
    theta = np.radians(degrees)
    wind = sea.get("wind_speed") or 0.877 * 9.81 / wp  # the PM-equivalent wind of the peak
    fetch_for_peak = _fetch_for_peak(wind, wp)
    for label, kw in (("power-cosine, α = 1", dict(model="power-cosine")),
                      ("cos-2s, s = 10", dict(model="cos2s", s=10.0)),
                      ("Mitsuyasu 1975", dict(model="mitsuyasu")),
                      ("Hasselmann 1980", dict(model="hasselmann")),
                      ("Donelan-Banner", dict(model="donelan-banner"))):
        d = ocean.spreading(theta, wind_speed=wind, fetch=fetch_for_peak, **kw)
        ax[0, 1].plot(degrees, d, label=label)
    ax[0, 1].set(title="Directional spreading D(θ) at ω = ωp", xlabel="θ, °", ylabel="D, 1/rad",
                 xlim=(-180, 180), ylim=(0, None))
    ax[0, 1].legend()

    depth = 10.0
    omega_h = np.linspace(0.01, 3.0, 300)
    w = omega_h * np.sqrt(9.81 / depth)
    ax[1, 0].plot(omega_h, ocean.depth_factor(w, depth=depth), lw=2, label="exact (Kitaigorodskii)")
    ax[1, 0].plot(omega_h, ocean.depth_factor(w, depth=depth, method="thompson-vincent"), "--",
                  label="Thompson-Vincent")
    ax[1, 0].set(title="TMA depth factor Φ(ωh)", xlabel="ωh = ω·√(h/g)", ylabel="Φ",
                 xlim=(0, None), ylim=(0, 1.1))
    ax[1, 0].legend()

    period = np.linspace(1.0, 20.0, 400)
    for h in (None, 50.0, 10.0, 3.0):
        d = ocean.dispersion(omega=2 * np.pi / period, depth=h)
        ax[1, 1].plot(period, d["wavelength_m"], label="deep water" if h is None else f"h = {h:.0f} m")
    ax[1, 1].set(title="Dispersion: wavelength against period", xlabel="T, s",
                 ylabel="wavelength, m", xlim=(0, None), ylim=(0, None))
    ax[1, 1].legend()
    return fig


def _fetch_for_peak(wind_speed, omega_p):
    """The fetch at which Hasselmann et al. (1973)'s law puts the peak at omega_p for this wind:
    omega_p = 2 pi 3.5 (g/U) (g F/U^2)^-0.33, inverted (ocean.spreading takes wind and fetch)."""
    g = 9.81
    x = (omega_p * wind_speed / (2 * np.pi * 3.5 * g)) ** (-1 / 0.33)
    return float(np.clip(x * wind_speed**2 / g, 1.0, 1e8))


def maps_figure(simulator, cascade=0):
    """Height, slope magnitude and foam maps of one cascade of the simulator's published frame."""
    import matplotlib.figure

    f = simulator.fields(cascade)
    size = simulator.patch_sizes[cascade]
    extent = (0, size, size, 0)
    height = np.array(f["height"])
    if "normal" in f:
        n = np.array(f["normal"], dtype=np.float64)
        slope = np.hypot(n[..., 0], n[..., 2]) / np.maximum(n[..., 1], 1e-6)
    else:
        step = size / height.shape[0]
        gz, gx = np.gradient(height, step)
        slope = np.hypot(gx, gz)
    foam = np.array(f["foam"]) if "foam" in f else np.array(f["packed"][..., 2]) / 255.0
    del f  # the views: the simulator may step again
    fig = matplotlib.figure.Figure(figsize=(15, 5), layout="constrained")
    fig.suptitle(f"Cascade {cascade} ({size:g} m) at t = {simulator.time:g} s")
    ax = fig.subplots(1, 3)
    for a, data, title, cmap in ((ax[0], height, "height, m", "RdBu_r"),
                                 (ax[1], slope, "slope |∇h|", "viridis"),
                                 (ax[2], foam, "foam coverage", "gray")):
        im = a.imshow(data, extent=extent, cmap=cmap)
        a.set(title=title, xlabel="x, m", ylabel="z, m")
        fig.colorbar(im, ax=a, shrink=0.8)
    return fig


def main(argv=None):
    """python3 -m ocean.figures {sea-state,maps} ... -o FILE.png"""
    import matplotlib

    matplotlib.use("Agg")
    parser = argparse.ArgumentParser(prog="python3 -m ocean.figures", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="figure", required=True)
    sea = sub.add_parser("sea-state", help="spectra, spreading, depth factor, dispersion")
    sea.add_argument("--model", default="jonswap")
    for flag in ("hs", "tp", "wind-speed", "fetch", "gamma", "depth"):
        sea.add_argument("--" + flag, type=float)
    maps = sub.add_parser("maps", help="height, slope and foam maps of a simulated frame")
    maps.add_argument("--preset", default=None, help="calm, moderate, storm or a preset file")
    maps.add_argument("--set", action="append", default=[], help="key=value override")
    maps.add_argument("--time", type=float, default=0.0)
    maps.add_argument("--cascade", type=int, default=0)
    for p in (sea, maps):
        p.add_argument("-o", "--output", required=True, help="the PNG file to write")
    args = parser.parse_args(argv)
    try:
        if args.figure == "sea-state":
            kw = {k: getattr(args, k) for k in ("hs", "tp", "wind_speed", "fetch", "gamma", "depth")}
            fig = sea_state_figure(args.model, **kw)
        else:
            preset = ocean.Preset(args.preset) if args.preset else ocean.Preset()
            for assignment in args.set:
                preset.set(assignment)
            sim = ocean.Simulator(preset)
            sim.step(args.time)
            fig = maps_figure(sim, args.cascade)
        fig.savefig(args.output, dpi=100)
    except (ValueError, OSError, NotImplementedError) as e:
        print(f"ocean.figures: error: {e}", file=sys.stderr)
        return 2 if isinstance(e, ValueError) else 1
    print(f"ocean.figures: wrote {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
