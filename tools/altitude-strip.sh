#!/usr/bin/env bash
# A picture of the sea from six heights (2 m, 20 m, 400 m, 3 km, 10 km and 400 km) for the calm,
# moderate and storm presets, one row per preset: what docs/rendering.md's far field is judged by.
# From 3 and 10 km the camera looks straight down through a field of view that frames the same
# 840 m of sea (16° and 5°, 3.3 m a pixel, fine enough for whitecaps), so the two differ by the
# air between; from 400 km the sea lies on a sphere of Earth's radius (--sphere), under the limb.
#   tools/altitude-strip.sh [OUT.png]      (default docs/images/altitude_strip.png)
# Needs a built `ocean` (build/release, or $OCEAN) and Debian's python3-matplotlib (./dev installs
# it) to set the renders side by side. Each render is 256 × 144 at `ocean render`'s defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
ocean="${OCEAN:-build/release/apps/ocean/ocean}"
out="${1:-docs/images/altitude_strip.png}"
[[ -x "$ocean" ]] || { echo "altitude-strip: no ocean binary at '$ocean' (build it: ./dev build)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
heights=(2 20 400 3000 10000 400000)
declare -A target=([2]="300,-2,60" [20]="400,0,80" [400]="800,0,300" [3000]="1,0,0" [10000]="1,0,0")
declare -A view=([2]="" [20]="" [400]="" [3000]="--fov 16" [10000]="--fov 5"
                [400000]="--sphere --altitude 400000 --target 0,-0.25,1 --fov 60")
for preset in calm moderate storm; do
  for h in "${heights[@]}"; do
    if [[ $h == 400000 ]]; then
      place=(--camera 0,0,0)
    else
      place=(--camera "0,$h,0" --target "${target[$h]}")
    fi
    # shellcheck disable=SC2086  # the view's flags are words
    "$ocean" render --preset "$preset" "${place[@]}" ${view[$h]} \
      --width 256 --height 144 --out "$work/${preset}_$h.png" >/dev/null
    echo "altitude-strip: $preset from $h m" >&2
  done
done
/usr/bin/python3 - "$work" "$out" <<'PY'
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg
import matplotlib.pyplot as plt
work, out = sys.argv[1], sys.argv[2]
presets, heights = ["calm", "moderate", "storm"], ["2", "20", "400", "3000", "10000", "400000"]
labels = {"3000": "3 000 m, straight down (16°)", "10000": "10 000 m, straight down (5°)",
          "400000": "400 km, the limb"}
fig, axes = plt.subplots(3, 6, figsize=(6 * 2.56, 3 * 1.44 + 0.5), dpi=100)
for r, p in enumerate(presets):
    for c, h in enumerate(heights):
        ax = axes[r][c]
        ax.imshow(mpimg.imread(f"{work}/{p}_{h}.png"))
        ax.set_xticks([]), ax.set_yticks([])
        if r == 0:
            ax.set_title(labels.get(h, f"{int(h):,} m".replace(",", " ")), fontsize=10)
        if c == 0:
            ax.set_ylabel(p, fontsize=10)
fig.subplots_adjust(left=0.03, right=0.995, top=0.93, bottom=0.005, wspace=0.02, hspace=0.02)
fig.savefig(out + ".tmp.png")
import os
os.replace(out + ".tmp.png", out)
PY
echo "altitude-strip: wrote $out" >&2
