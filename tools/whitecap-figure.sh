#!/usr/bin/env bash
# Whitecap coverage against Monahan & O'Muircheartaigh (1980), docs/images/whitecaps.png:
# `ocean stats` of the moderate preset's sea at wind speeds 3–25 m/s — the whitecap fraction a
# renderer draws with the breaking source (docs/math.md M.7.4) and with the ramp, beside
# Monahan's W = 3.84e-6·U10^3.41 with a factor-2 band and Longuet-Higgins's criterion on a
# Gaussian sea of Cox & Munk's slope variance, Φ(−½/σ_CM).
#   tools/whitecap-figure.sh [OUT.png]      (default docs/images/whitecaps.png)
# Needs a built `ocean` (build/release, or $OCEAN) and Debian's python3-matplotlib.
set -euo pipefail
cd "$(dirname "$0")/.."
ocean="${OCEAN:-build/release/apps/ocean/ocean}"
out="${1:-docs/images/whitecaps.png}"
[[ -x "$ocean" ]] || { echo "whitecap-figure: no ocean binary at '$ocean' (build it: ./dev build)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
speeds=(3 4 5 6 7.5 9 10 12.5 15 17.5 20 25)
i=0
for u in "${speeds[@]}"; do
  i=$((i + 1))
  printf '\rwhitecap-figure: %d/%d wind speeds' "$i" "${#speeds[@]}" >&2
  for source in breaking ramp; do
    "$ocean" stats --preset moderate --set "sea.wind_sea.wind_speed_mps=$u" \
      --set "foam.source=$source" --seeds 2 --time 4 --json >"$work/$source-$u.json"
  done
done
echo >&2
/usr/bin/python3 - "$work" "$out" <<'PY'
import glob, json, math, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
work, out = sys.argv[1], sys.argv[2]
def load(source):
    rows = [json.load(open(f)) for f in glob.glob(os.path.join(work, source + "-*.json"))]
    return sorted(rows, key=lambda j: j["wind_speed_mps"])
breaking, ramp = load("breaking"), load("ramp")
u = [j["wind_speed_mps"] for j in breaking]
law = [3.84e-6 * v ** 3.41 for v in u]
fine = [3 + 0.1 * i for i in range(221)]
fig, ax = plt.subplots(figsize=(7.5, 5))
ax.fill_between(fine, [50 * 3.84e-6 * v ** 3.41 for v in fine],
                [200 * 3.84e-6 * v ** 3.41 for v in fine], color="0.88",
                label="Monahan × ½ … × 2")
ax.plot(fine, [100 * 3.84e-6 * v ** 3.41 for v in fine], "k-",
        label="Monahan & O'Muircheartaigh (1980): 3.84e-6·U10^3.41")
gauss = [100 * 0.5 * math.erfc(0.5 / math.sqrt(0.003 + 5.12e-3 * 1.03 * v) / math.sqrt(2))
         for v in fine]
ax.plot(fine, gauss, ":", color="tab:green",
        label="Φ(−½/σ): Longuet-Higgins's α = ½ on a Cox–Munk sea")
ax.plot(u, [100 * j["whitecap_coverage"] for j in breaking], "o-", color="tab:blue",
        label="simulated, breaking source (default)")
ax.plot(u, [100 * j["whitecap_coverage"] for j in ramp], "s--", color="tab:orange",
        label="simulated, per-cascade ramp")
ax.set_yscale("log")
ax.set_xlabel("wind speed U10, m/s")
ax.set_ylabel("whitecap coverage, % of the surface")
ax.set_title("Whitecaps of the moderate preset's sea (4 cascades at N = 256)", fontsize=11)
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=8, loc="lower right")
for v, j, w in zip(u, breaking, law):
    print(f"U10 {v:5.1f} m/s: breaking {100 * j['whitecap_coverage']:.4f} %, Monahan "
          f"{100 * w:.4f} %, ratio {j['whitecap_coverage'] / w:.2f}")
fig.tight_layout()
tmp = out + ".tmp.png"
fig.savefig(tmp, dpi=110)
os.replace(tmp, out)
print("whitecap-figure: wrote", out)
PY
