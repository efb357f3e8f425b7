#!/usr/bin/env bash
# The Kelvin wake's figures in docs/waves.md, from `ocean bake --calm` layers:
#   docs/images/kelvin_envelope_profiles.png — |h| across the track 3, 8 and 20 hull lengths
#     behind a hull at Fr = 0.2: as it is, smoothed over a few samples (as the envelope test
#     measures it), its envelope (the analytic signal of h along the track, W.18), the amplitude
#     of Havelock's integral computed without the layer, and Kelvin's 19.47° line;
#   docs/images/kelvin_construction.png — the wake of docs/images/kelvin_wake_top.png from above,
#     beside Kelvin's construction drawn over it.
#   tools/kelvin-figures.sh [OUT_DIR]      (default docs/images)
# Needs a built `ocean` (build/release, or $OCEAN) and Debian's python3-matplotlib (./dev installs
# it). Rerun it after changing the wake (src/waves/kelvin_table.cpp).
set -euo pipefail
cd "$(dirname "$0")/.."
ocean="${OCEAN:-build/release/apps/ocean/ocean}"
out="${1:-docs/images}"
[[ -x "$ocean" ]] || { echo "kelvin-figures: no ocean binary at '$ocean' (build it: ./dev build)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# Fr = 0.2: L = 20 m, U = 0.2·√(9.81·20) = 2.8014 m/s, 2πU²/g = 5.03 m = 10 cells of 0.5 m.
"$ocean" bake --calm --kelvin-wake 496,0,0,2.8014,20 --local-area -4,-256,512 \
  --local-resolution 1024 --out "$work/profiles" >/dev/null
# The wake of docs/images/kelvin_wake_top.png: Fr = 0.3 (L = 20 m, U = 4.2 m/s).
"$ocean" bake --calm --kelvin-wake 100,0,0,4.2,20 --local-area -120,-120,240 \
  --local-resolution 1024 --out "$work/top" >/dev/null
/usr/bin/python3 - "$work" "$out" <<'PY'
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

work, out = sys.argv[1], sys.argv[2]
kelvin = np.degrees(np.arcsin(1.0 / 3.0))


def save(fig, name):
    path = os.path.join(out, name)
    fig.savefig(path + ".tmp.png")
    os.replace(path + ".tmp.png", path)
    print(f"kelvin-figures: wrote {path}", file=sys.stderr)


# |h| across the track, smoothed, its envelope, and Havelock's integral. The layer's rows run along
# +z, its columns along +x; the object heads +x from x = 496, so s = 496 − x behind it and ζ = z to
# its left.
h = np.load(f"{work}/profiles/local_height_f00000.npy").astype(np.float64)
n, x0, z0, size, x_obj, hull, speed = h.shape[0], -4.0, -256.0, 512.0, 496.0, 20.0, 2.8014
g = 9.81
k0 = g / speed**2
wavelength = 2.0 * np.pi / k0
cell = size / n
xs = x0 + (np.arange(n) + 0.5) * cell
zs = z0 + (np.arange(n) + 0.5) * cell
behind = xs <= x_obj
line = h[:, behind][:, ::-1]  # along s from the object backwards
s = (x_obj - xs[behind])[::-1]
m = 1 << int(np.ceil(np.log2(2 * line.shape[1])))
spectrum = np.fft.fft(line, m, axis=1)
spectrum[:, 1 : m // 2] *= 2.0
spectrum[:, m // 2 + 1 :] = 0.0
envelope = np.abs(np.fft.ifft(spectrum, axis=1)[:, : line.shape[1]])
left = zs > 0


def height_at(x, z):
    """The layer's heights at world (x, z), bilinear between the cell centres (the border cells'
    values beyond them)."""
    fx = np.clip((x - x0) / cell - 0.5, 0.0, n - 1.001)
    fz = np.clip((z - z0) / cell - 0.5, 0.0, n - 1.001)
    ix, iz = np.floor(fx).astype(int), np.floor(fz).astype(int)
    tx, tz = fx - ix, fz - iz
    return ((1 - tx) * ((1 - tz) * h[iz, ix] + tz * h[iz + 1, ix])
            + tx * ((1 - tz) * h[iz, ix + 1] + tz * h[iz + 1, ix + 1]))


def smoothed(s_row):
    """|h| at the cells' ζ > 0, its mean under a Hann window one transverse wavelength long along
    the ray from the object, then over 3 samples across (tests/waves/kelvin_envelope_test.cpp)."""
    reach = int(round(0.5 * wavelength / cell))
    z = zs[left]
    total, weights = np.zeros(z.size), 0.0
    for i in range(-reach, reach + 1):
        w = 0.5 + 0.5 * np.cos(np.pi * i / (reach + 1))
        along = s_row + i * cell
        total += w * np.abs(height_at(np.full(z.size, x_obj - along), z * along / s_row))
        weights += w
    mean = total / weights
    padded = np.concatenate(([mean[0]], mean, [mean[-1]]))
    return (padded[:-2] + padded[1:-1] + padded[2:]) / 3.0


def havelock(s_row, zeta):
    """|F| of Havelock's integral for the wake's pressure (docs/waves.md W.3, W.4), no grid: Filon's
    rule over u = tanθ, amplitude and phase linear on each step."""
    a, beta = np.sqrt(2.0) * hull / (2.0 * np.pi), 0.35

    def weight(u):
        k = k0 * (1 + u * u)
        ka2 = (k * a) ** 2
        return ka2 / (1 + ka2 * (1 + beta**2 * u * u) / (1 + u * u)) ** 1.5 / (1 + u * u)

    u_max = 1.0
    while weight(u_max) > 1e-3 * weight(np.sqrt(0.5)):
        u_max *= 1.1
    steps = int(np.ceil(2 * u_max / np.sqrt(0.01 / (k0 * (s_row + 2 * zeta.max())))))
    u = np.linspace(-u_max, u_max, steps + 1)
    w, sec = weight(u), np.sqrt(1 + u * u)
    out = []
    for z in zeta:
        p = k0 * sec * (s_row + z * u)
        d = np.diff(p)
        small = np.abs(d) < 1e-3
        dd = np.where(small, 1.0, d)
        ed = np.exp(1j * dd)
        e0 = np.where(small, 1 - d * d / 6 + 0.5j * d, (ed - 1) / (1j * dd))
        e1 = np.where(small, 0.5 - d * d / 8 + 1j * d / 3, ed / (1j * dd) + (ed - 1) / dd**2)
        out.append(abs(np.sum(np.exp(1j * p[:-1]) * (w[:-1] * e0 + np.diff(w) * e1))))
    return np.array(out)


def half_max_edge(angle, e):
    top = e.max()
    half = np.nonzero(e >= 0.5 * top)[0].max()
    f = (e[half] - 0.5 * top) / (e[half] - e[half + 1])
    return angle[half] + f * (angle[half + 1] - angle[half])


fig, axes = plt.subplots(3, 1, figsize=(9, 9.6), dpi=100, sharex=True)
for ax, hulls in zip(axes, [3, 8, 20]):
    i = int(np.argmin(np.abs(s - hulls * hull)))
    angle = np.degrees(np.arctan2(zs[left], s[i]))
    e = envelope[left, i]
    top = e.max()
    sm = smoothed(s[i])
    fine = np.radians(np.linspace(0.0, 25.0, 1001))
    ref = havelock(s[i], s[i] * np.tan(fine))
    ax.plot(angle, np.abs(line[left, i]) / top, color="0.65", lw=0.8, label="|h|")
    ax.plot(angle, e / top, color="tab:blue", lw=1.6, label="envelope |h + i·H(h)|")
    ax.plot(angle, sm / sm.max(), color="tab:orange", lw=2.0,
            label="|h| smoothed over a few samples")
    ax.plot(np.degrees(fine), ref / ref.max(), color="black", lw=0.7, ls="--",
            label="Havelock's integral |F| (no grid)")
    ax.axvline(kelvin, color="tab:red", ls="--", lw=1.5, label=f"Kelvin {kelvin:.2f}°")
    ax.axhline(0.5, color="0.3", ls=":", lw=1.0)
    edge = half_max_edge(angle, sm)
    ref_edge = half_max_edge(np.degrees(fine), ref)
    ax.plot([edge], [0.5], "o", color="tab:orange")
    ax.annotate(f"smoothed |h|: half maximum at {edge:.2f}°\nHavelock: {ref_edge:.2f}°",
                (edge, 0.5), xytext=(10, 14), textcoords="offset points", color="tab:orange")
    ax.set_xlim(0, 25)
    ax.set_ylim(0, 1.15)
    ax.set_ylabel("relative to its maximum")
    ax.set_title(f"{hulls} hull lengths ({s[i]:.0f} m) behind", fontsize=11)
    if hulls == 3:
        ax.legend(loc="upper left", fontsize=8)
axes[-1].set_xlabel("angle from the track, atan(ζ/s), degrees")
fig.suptitle("Kelvin wake at Fr = 0.2 (L = 20 m, U = 2.80 m/s): heights across the track",
             fontsize=12)
fig.tight_layout()
save(fig, "kelvin_envelope_profiles.png")

# The wake from above beside Kelvin's construction: a wave group made where the object was, a
# distance d behind it, has travelled at half its phase speed U·cosθ, so the groups of every
# angle θ lie on the circle of diameter d/2 through that point towards the object (centre 3d/4
# behind the object, radius d/4); the lines from the object tangent to all those circles make
# asin((d/4)/(3d/4)) = asin(1/3) with the track.
h = np.load(f"{work}/top/local_height_f00000.npy").astype(np.float64)
extent = (-120, 120, 120, -120)  # +x right, +z down, as docs/images/kelvin_wake_top.png
ox, oz = 100.0, 0.0
fig, axes = plt.subplots(1, 2, figsize=(14, 7.2), dpi=100)
for ax in axes:
    ax.set_xlabel("x, m")
    ax.set_ylabel("z, m")
axes[0].imshow(h, cmap="gray", vmin=-0.4, vmax=0.4, extent=extent)
axes[0].set_title("Heights from above, Fr = 0.3 (L = 20 m, U = 4.2 m/s)", fontsize=11)
axes[1].imshow(h, cmap="gray", vmin=-0.8, vmax=0.8, extent=extent, alpha=0.7)
t = np.linspace(0, 2 * np.pi, 200)
for d in [40, 80, 120, 160, 200]:
    cx = ox - 0.75 * d
    axes[1].plot(cx + 0.25 * d * np.cos(t), oz + 0.25 * d * np.sin(t), color="tab:blue", lw=1.2)
    axes[1].plot([ox - d], [oz], "o", color="tab:blue", ms=4)
    axes[1].annotate(f"d = {d} m", (ox - d, oz), xytext=(0, 7), textcoords="offset points",
                     ha="center", fontsize=8, color="tab:blue",
                     bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8})
reach = 230.0
for sign in (1, -1):
    a = np.radians(kelvin)
    axes[1].plot([ox, ox - reach * np.cos(a)], [oz, oz + sign * reach * np.sin(a)],
                 color="tab:red", lw=1.8)
axes[1].plot([ox], [oz], "o", color="tab:red", ms=6)
axes[1].annotate("object", (ox, oz), xytext=(0, 9), textcoords="offset points", ha="center",
                 color="tab:red")
axes[1].plot([ox - reach, ox], [oz, oz], color="0.3", lw=0.8, ls=":")
axes[1].set_xlim(-120, 120)
axes[1].set_ylim(120, -120)
axes[1].set_title("Kelvin's construction: the waves made d behind the object lie on a circle\n"
                  f"of radius d/4; its tangents make asin(1/3) = {kelvin:.2f}° with the track",
                  fontsize=11)
fig.tight_layout()
save(fig, "kelvin_construction.png")
PY
