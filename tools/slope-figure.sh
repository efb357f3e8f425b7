#!/usr/bin/env bash
# The sea's slopes against Cox & Munk (1954), docs/images/cox_munk_slopes.png: `ocean stats` of the
# moderate preset's sea at wind speeds 2–16 m/s — the cascades' slope variance, the waves shorter
# than the finest cascade (docs/math.md M.9) and their sum, up- and crosswind — beside Cox & Munk's
# clean-surface lines with their ±0.004 scatter.
#   tools/slope-figure.sh [OUT.png]      (default docs/images/cox_munk_slopes.png)
# Needs a built `ocean` (build/release, or $OCEAN) and Debian's python3-matplotlib.
set -euo pipefail
cd "$(dirname "$0")/.."
ocean="${OCEAN:-build/release/apps/ocean/ocean}"
out="${1:-docs/images/cox_munk_slopes.png}"
[[ -x "$ocean" ]] || { echo "slope-figure: no ocean binary at '$ocean' (build it: ./dev build)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for u in 2 3 4 5 6 7 8 10 12 14 16; do
  "$ocean" stats --preset moderate --set "sea.wind_sea.wind_speed_mps=$u" --seeds 2 --json \
    >"$work/$u.json"
done
/usr/bin/python3 - "$work" "$out" <<'PY'
import glob, json, os, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
work, out = sys.argv[1], sys.argv[2]
rows = sorted((json.load(open(f)) for f in glob.glob(os.path.join(work, "*.json"))),
              key=lambda j: j["wind_speed_mps"])
u = [j["wind_speed_mps"] for j in rows]
fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), sharey=False)
lines = {"total": (lambda v: 0.003 + 5.12e-3 * v, "resolved_mss", "unresolved_mss", "σ² = σu² + σc²"),
         "upwind": (lambda v: 3.16e-3 * v, "resolved_mss_upwind", "unresolved_mss_upwind", "σu²"),
         "crosswind": (lambda v: 0.003 + 1.92e-3 * v, "resolved_mss_crosswind",
                       "unresolved_mss_crosswind", "σc²")}
for ax, (name, (cm, res, unres, label)) in zip(axes, lines.items()):
    if name == "total":
        r = [j["resolved_mss_upwind"] + j["resolved_mss_crosswind"] for j in rows]
        t = [j["total_mss"] for j in rows]
    else:
        r = [j[res] for j in rows]
        t = [j[res] + j[unres] for j in rows]
    c = [cm(v) for v in u]
    ax.fill_between(u, [x - 0.004 for x in c], [x + 0.004 for x in c], color="0.85",
                    label="Cox & Munk ±0.004")
    ax.plot(u, c, "k-", label="Cox & Munk (1954), clean surface")
    ax.plot(u, t, "o-", color="tab:blue", label="cascades + shorter waves")
    ax.plot(u, r, "s--", color="tab:orange", label="cascades alone")
    ax.set_xlabel("wind speed U10, m/s")
    ax.set_title(label + " (" + name + ")")
    ax.grid(alpha=0.3)
axes[0].set_ylabel("mean-square slope")
axes[0].legend(fontsize=8, loc="upper left")
fig.suptitle("Slopes of the moderate preset's sea (cascades 1000, 233, 57, 13 m at N = 256) "
             "against the sun-glitter law", fontsize=11)
fig.tight_layout()
tmp = out + ".tmp.png"
fig.savefig(tmp, dpi=110)
os.replace(tmp, out)
print("slope-figure: wrote", out)
PY
