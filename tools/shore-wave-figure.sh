#!/usr/bin/env bash
# The peak wave refracted and shoaled towards a beach, docs/images/beach_shore_wave_heights.png:
# `ocean query` heights on a 2 m grid over the 400 m round the origin of `--shallows beach` (the
# calm preset with a swell of Hs 1.5 m, Tp 9 s, travelling 15° from +x towards −z), with the
# shore wave (docs/waves.md W.32–W.38) and without it (its layer moved away by --local-area),
# the shoreline dashed. Each call queries 25 rows (a command line holds about 128 kB).
#   tools/shore-wave-figure.sh [OUT.png]      (default docs/images/beach_shore_wave_heights.png)
# Needs a built `ocean` (build/release, or $OCEAN) and Debian's python3-matplotlib.
set -euo pipefail
cd "$(dirname "$0")/.."
ocean="${OCEAN:-build/release/apps/ocean/ocean}"
out="${1:-docs/images/beach_shore_wave_heights.png}"
[[ -x "$ocean" ]] || { echo "shore-wave-figure: no ocean binary at '$ocean' (build it: ./dev build)" >&2; exit 1; }
/usr/bin/python3 - "$ocean" "$out" <<'PY'
import subprocess, sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
ocean, out = sys.argv[1], sys.argv[2]
scene = ["--preset", "calm", "--set", "sea.swell.hs_m=1.5", "--set", "sea.swell.tp_s=9",
         "--shallows", "beach"]
xs = np.arange(-200.0, 200.1, 2.0)

def heights(extra):
    h = np.zeros((len(xs), len(xs)))
    for r0 in range(0, len(xs), 25):
        rows = xs[r0:r0 + 25]
        at = ";".join(f"{x:g},{z:g}" for z in rows for x in xs)
        text = subprocess.run([ocean, "query", *scene, *extra, "--at", at], check=True,
                              capture_output=True, text=True).stdout.split("\n")
        values = [float(line.split()[2]) for line in text[1:] if line.strip()]
        h[r0:r0 + len(rows)] = np.array(values).reshape(len(rows), len(xs))
    return h

without = heights(["--local-area", "3000,3000,50", "--local-resolution", "64"])
with_wave = heights([])
fig, axes = plt.subplots(1, 2, figsize=(10, 4.8), constrained_layout=True)
c, s = np.cos(np.radians(35.0)), np.sin(np.radians(35.0))  # the beach's normal (shallows.hpp)
for a, h, title in zip(axes, [without, with_wave],
                       ["the low band damped (W.12), no shore wave",
                        "with the shore wave (W.32–W.38)"]):
    im = a.imshow(h, extent=[-201, 201, 201, -201], cmap="gray", vmin=-1, vmax=1)
    z = np.linspace(-200, 200, 10)
    a.plot((100.0 - z * s) / c, z, "y--", lw=1)  # the shoreline, 100 m out along the normal
    a.set_xlim(-200, 200)
    a.set_ylim(200, -200)
    a.set_title(title)
    a.set_xlabel("x, m")
    a.set_ylabel("z, m")
fig.colorbar(im, ax=axes, shrink=0.9, label="height, m")
fig.savefig(out, dpi=80)
PY
