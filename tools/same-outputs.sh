#!/usr/bin/env bash
# same-outputs.sh OLD_BUILD NEW_BUILD — runs the same ~40 commands with two builds of the project
# (each a CMake build folder, or a copy of one holding apps/ocean/ocean, python/ocean and
# src/capi/libocean_c.so) and compares every output byte for byte: pictures, bakes, meshes,
# JSON and the text a command prints (lines that report timings are left out of the text).
# For a restructure that must not change behaviour: build the old commit in a worktree
#   git worktree add /tmp/old HEAD~1 && cmake --preset release -S /tmp/old -B /tmp/old/build ...
# then run  tools/same-outputs.sh /tmp/old/build build/release
# SAME_OUTPUTS_ONLY=REGEX runs only the command cases whose names match (the C and Python cases
# always run). Prints one line a case (same / DIFFERENT / FAILED) and exits 1 when any case differs.
set -u
if [[ $# -ne 2 ]]; then
  echo "usage: tools/same-outputs.sh OLD_BUILD NEW_BUILD" >&2
  exit 2
fi
old=$(cd "$1" && pwd) || exit 2
new=$(cd "$2" && pwd) || exit 2
repo=$(cd "$(dirname "$0")/.." && pwd)
for b in "$old" "$new"; do
  [[ -x $b/apps/ocean/ocean ]] || { echo "same-outputs: $b/apps/ocean/ocean is missing" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OCEAN_NO_PROGRESS=1

# Inputs some cases read: a height map and a damping mask as .npy (written by Python's numpy).
/usr/bin/python3 - "$work" <<'EOF'
import sys, numpy as np
d = sys.argv[1]
x = np.linspace(-1, 1, 64)
X, Z = np.meshgrid(x, x)
np.save(f"{d}/bump.npy", (np.exp(-8 * (X * X + Z * Z))).astype(np.float32))
np.save(f"{d}/mask.npy", np.clip(0.5 + X, 0, 1).astype(np.float32))
np.save(f"{d}/depth.npy", (2.0 + 30.0 * (X + 1)).astype(np.float32))
EOF

S=(--width 240 --height 136)
cases=(
  "render_default|render ${S[*]} --out OUT/a.png"
  "render_storm_exr|render ${S[*]} --preset storm --out OUT/a.exr"
  "render_calm_sunset|render ${S[*]} --preset calm --sky sunset --exposure 0.6 --out OUT/a.png"
  "render_vulkan|render ${S[*]} --backend vulkan --out OUT/a.png"
  "render_high|render ${S[*]} --camera 0,3000,0 --target 2000,0,500 --out OUT/a.png"
  "render_down|render ${S[*]} --camera 0,10000,0 --target 1,0,0 --fov 50 --out OUT/a.png"
  "render_flat|render ${S[*]} --planet-radius inf --far-noise-resolution 0 --out OUT/a.png"
  "render_far|render ${S[*]} --camera 10000000,8,-3000000 --target 10000300,0,-2999940 --out OUT/a.png"
  "render_tess|render ${S[*]} --mesh tessellation --out OUT/a.png"
  "render_lod_view|render ${S[*]} --view lod --out OUT/a.png"
  "render_wire|render ${S[*]} --view wireframe --quality low --out OUT/a.png"
  "render_normals|render ${S[*]} --view normals --normals analytic --out OUT/a.png"
  "render_stereo|render ${S[*]} --stereo --ipd 0.07 --out OUT/a.png"
  "render_sphere|render ${S[*]} --sphere --altitude 400000 --latitude 30 --longitude 20 --camera 0,0,0 --target 0,-1,1000 --out OUT/a.png"
  "render_seabed|render ${S[*]} --preset calm --seabed 6 --camera 0,4,0 --target 20,-3,5 --out OUT/a.png"
  "render_underwater|render ${S[*]} --camera 0,-3,0 --target 30,1,0 --out OUT/a.png"
  "render_objects|render ${S[*]} --object boat,40,0,8,30 --object buoy,25,0,-6 --object box,30,0,0 --out OUT/a.png"
  "render_float|render ${S[*]} --object boat,20,0,0,0,6 --float --time 1.5 --warmup 0 --camera -10,8,-25 --target 30,0,0 --out OUT/a.png"
  "render_wake|render ${S[*]} --calm --kelvin-wake 0,0,0,6,20 --local-area -100,-100,200 --local-resolution 128 --camera 0,60,-80 --target 0,0,0 --out OUT/a.png"
  "render_waveform|render ${S[*]} --waveform WORK/bump.npy,30,0,20,1.5 --local-area 0,-30,60 --local-resolution 128 --out OUT/a.png"
  "render_damping|render ${S[*]} --damping-mask WORK/mask.npy,-200,-200,800 --bathymetry WORK/depth.npy,0,-400,800 --out OUT/a.png"
  "render_sequence|render ${S[*]} --frames 3 --fps 10 --time 5 --warmup 1 --out OUT/seq_%03d.png"
  "render_motion|render ${S[*]} --frames 2 --motion-vectors OUT/motion.png --out OUT/a.png"
  "render_contact|render --contact-sheet OUT/sheet.png --width 120 --height 68"
  "render_band_roles|render ${S[*]} --band-roles displace,both,both,shade --out OUT/a.png"
  "render_range|render ${S[*]} --far-field-range 300,900 --far-noise-resolution 128 --out OUT/a.png"
  "bake_png|bake --resolution 64 --frames 2 --out OUT/bake --format png"
  "bake_exr_wake|bake --resolution 64 --frames 2 --kelvin-wake 0,0,30,5,12 --local-area -80,-80,160 --local-resolution 64 --out OUT/bake --format exr"
  "bake_npy|bake --preset storm --resolution 32 --cascades 400,97 --frames 1 --out OUT/bake --format npy"
  "stats|stats --resolution 64 --seeds 2 --json"
  "stats_tma|stats --model tma --depth 12 --wind-speed 14 --fetch 3e4 --resolution 64 --seeds 1 --json"
  "query|query --time 3 --at '0,0;12.5,-7;300,40' --json"
  "query_wake|query --calm --kelvin-wake 0,0,0,6,20 --local-area -100,-100,200 --local-resolution 128 --time 10 --at '-20,5;-40,12'"
  "lod|lod --camera 0,20,0 --target 100,0,30 --json --out OUT/mesh.obj --png OUT/lod.png"
  "spectrum|spectrum --model jonswap --wind-speed 12 --fetch 5e4 --omega 0.5,0.8,1.2,2 --json"
  "spectrum_plot|spectrum --hs 3 --tp 9 --plot OUT/sea.png"
  "dispersion|dispersion --depth 8 --k 0.05,0.3,2 --json"
  "spreading|spreading --model cos2s --s 8 --theta -1,0,0.5,2 --json"
  "validate_vulkan|validate --backend vulkan --json"
)

# The C ABI and Python read the same plan: one script each through both builds.
py_case='import ocean, hashlib, numpy as np
p = ocean.Preset("moderate").set("resolution=64")
sim = ocean.Simulator(p)
sim.step(3.0)
for c in range(4):
    f = sim.fields(c)
    for k in sorted(f):
        print(k, hashlib.sha1(np.ascontiguousarray(f[k]).tobytes()).hexdigest())
    del f
print(sim.heights(np.array([[0.0, 0.0], [10.0, 5.0]])).tolist())
w = np.linspace(0.2, 3.0, 50)
print(ocean.spectrum("jonswap", omega=w, wind_speed=12.0, fetch=50e3).tolist())
print(ocean.dispersion(omega=w, depth=20.0)["k"].tolist())'

run_case() {  # build name command...
  local build=$1 name=$2 cmd=$3 out=$work/$1/$2
  mkdir -p "$out"
  cmd=${cmd//OUT/$out}
  cmd=${cmd//WORK/$work}
  (cd "$out" && eval "\"$build_dir/apps/ocean/ocean\" $cmd" >"$out/stdout.txt" 2>"$out/stderr.txt")
  echo $? >"$out/rc.txt"
  # Timings and the output folder's own path differ by nature.
  sed -i -E -e "s#$out#OUT#g" -e '/([0-9.]+ ?(ms|s)\b.*(per frame|elapsed|took))|GPU [0-9.]+ ms|done in [0-9.]+ s|"(seconds|elapsed_s|ms|time_ms|gpu_ms|wall_s)":/d' \
    "$out/stdout.txt" "$out/stderr.txt"
}

status=0
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  cmd=${entry#*|}
  [[ -n ${SAME_OUTPUTS_ONLY:-} && ! $name =~ $SAME_OUTPUTS_ONLY ]] && continue
  for side in old new; do
    if [[ $side == old ]]; then build_dir=$old; else build_dir=$new; fi
    run_case "$side" "$name" "$cmd"
  done
  if diff -r "$work/old/$name" "$work/new/$name" >"$work/diff.txt" 2>&1; then
    if [[ $(cat "$work/new/$name/rc.txt") == 0 ]]; then
      printf '%-22s same (%s files)\n' "$name" "$(find "$work/new/$name" -type f | wc -l)"
    else
      printf '%-22s same, but both FAILED: %s\n' "$name" "$(head -c 200 "$work/new/$name/stderr.txt")"
      status=1
    fi
  else
    printf '%-22s DIFFERENT\n' "$name"
    head -20 "$work/diff.txt" | sed 's/^/    /'
    status=1
  fi
  rm -rf "$work/old/$name" "$work/new/$name"
done

cat >"$work/capi.c" <<'END'
#include <stdio.h>
#include "ocean/ocean.h"
static unsigned long fnv(const unsigned char* p, size_t n) {
  unsigned long h = 1469598103934665603UL;
  for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211UL;
  return h;
}
int main(void) {
  ocean_config* c = NULL;
  ocean_simulator* s = NULL;
  if (ocean_config_create(&c) || ocean_config_merge_preset(c, "storm") ||
      ocean_config_set(c, "resolution=64") || ocean_simulator_create(c, "cpu", &s) ||
      ocean_simulator_step(s, 4.0)) {
    printf("error %s\n", ocean_last_error());
    return 1;
  }
  size_t n = 0;
  ocean_simulator_cascade_count(s, &n);
  for (size_t i = 0; i < n; ++i)
    for (int f = 0; f <= 5; ++f) {
      ocean_field_view v = {.struct_size = sizeof v};
      if (ocean_simulator_field(s, i, (ocean_field)f, 0, &v) == 0)
        printf("%zu %d %lx\n", i, f, fnv(v.data, v.row_stride_bytes * (size_t)v.height));
    }
  double x[2] = {0, 7}, z[2] = {0, -3}, h[2];
  ocean_simulator_heights(s, x, z, 2, h);
  printf("%.17g %.17g\n", h[0], h[1]);
  ocean_spectrum_params p;
  ocean_spectrum_params_init(&p);
  p.wind_speed_mps = 12, p.fetch_m = 5e4;
  double w[3] = {0.5, 0.9, 2}, S[3];
  ocean_spectrum_evaluate(&p, w, 3, S);
  printf("%.17g %.17g %.17g\n", S[0], S[1], S[2]);
  ocean_simulator_destroy(s);
  ocean_config_destroy(c);
  return 0;
}
END
for side in old new; do
  if [[ $side == old ]]; then build_dir=$old; else build_dir=$new; fi
  if cc -std=c11 -I "$repo/include" "$work/capi.c" -L "$build_dir/src/capi" -locean_c \
       -Wl,-rpath,"$build_dir/src/capi" -o "$work/capi_$side" 2>"$work/capi_$side.txt"; then
    "$work/capi_$side" >"$work/capi_$side.txt" 2>&1
    echo "rc $?" >>"$work/capi_$side.txt"
  fi
done
if cmp -s "$work/capi_old.txt" "$work/capi_new.txt" && grep -q '^rc 0$' "$work/capi_new.txt"; then
  printf '%-22s same\n' c_api
else
  printf '%-22s DIFFERENT or FAILED\n' c_api
  diff "$work/capi_old.txt" "$work/capi_new.txt" | head -10 | sed 's/^/    /'
  head -3 "$work/capi_new.txt" | sed 's/^/    /'
  status=1
fi

for side in old new; do
  if [[ $side == old ]]; then build_dir=$old; else build_dir=$new; fi
  if [[ -d $build_dir/python/ocean ]]; then
    PYTHONPATH=$build_dir/python /usr/bin/python3 -c "$py_case" >"$work/py_$side.txt" 2>&1
    echo "rc $?" >>"$work/py_$side.txt"
  else
    echo "no python package" >"$work/py_$side.txt"
  fi
done
if cmp -s "$work/py_old.txt" "$work/py_new.txt"; then
  printf '%-22s same\n' python
  grep -q '^rc 0$' "$work/py_new.txt" || { echo "    but it failed: $(head -3 "$work/py_new.txt")"; status=1; }
else
  printf '%-22s DIFFERENT\n' python
  diff "$work/py_old.txt" "$work/py_new.txt" | head -10 | sed 's/^/    /'
  status=1
fi
exit $status
