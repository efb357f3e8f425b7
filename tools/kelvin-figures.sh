#!/usr/bin/env bash
# The Kelvin wake's figures in docs/waves.md, from `ocean bake --calm` layers:
#   docs/images/kelvin_envelope_profiles.png — |h| across the track 3, 8 and 20 hull lengths
#     behind a hull at Fr = 0.2, with its envelope (the analytic signal of h along the track,
#     W.18) and Kelvin's 19.47° line;
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


# |h| across the track and its envelope. The layer's rows run along +z, its columns along +x;
# the object heads +x from x = 496, so s = 496 − x behind it and ζ = z to its left.
h = np.load(f"{work}/profiles/local_height_f00000.npy").astype(np.float64)
n, x0, z0, size, x_obj, hull = h.shape[0], -4.0, -256.0, 512.0, 496.0, 20.0
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
fig, axes = plt.subplots(3, 1, figsize=(9, 8.4), dpi=100, sharex=True)
for ax, hulls in zip(axes, [3, 8, 20]):
    i = int(np.argmin(np.abs(s - hulls * hull)))
    angle = np.degrees(np.arctan2(zs[left], s[i]))
    e = envelope[left, i]
    top = e.max()
    half = np.nonzero(e >= 0.5 * top)[0].max()
    f = (e[half] - 0.5 * top) / (e[half] - e[half + 1])
    edge = angle[half] + f * (angle[half + 1] - angle[half])
    ax.plot(angle, np.abs(line[left, i]) / top, color="0.6", lw=0.8,
            label="|h|")
    ax.plot(angle, e / top, color="tab:blue", lw=2.0, label="envelope |h + i·H(h)|")
    ax.axvline(kelvin, color="tab:red", ls="--", lw=1.5, label=f"Kelvin {kelvin:.2f}°")
    ax.axhline(0.5, color="0.3", ls=":", lw=1.0)
    ax.plot([edge], [0.5], "o", color="tab:blue")
    ax.annotate(f"half maximum at {edge:.2f}°", (edge, 0.5), xytext=(8, 8),
                textcoords="offset points", color="tab:blue")
    ax.set_xlim(0, 25)
    ax.set_ylim(0, 1.15)
    ax.set_ylabel("|h| / max envelope")
    ax.set_title(f"{hulls} hull lengths ({s[i]:.0f} m) behind", fontsize=11)
    ax.legend(loc="upper left", fontsize=9)
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
