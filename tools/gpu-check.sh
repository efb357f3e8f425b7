#!/usr/bin/env bash
# The GPU checks, in one run on an NVIDIA machine (16 cores, the packages of ./dev, minutes of GPU
# time): builds only what they need, then runs the CUDA and Vulkan conformance tests against the
# CPU reference pipeline, the CUDA backend's render against the CPU backend's (its frames shared
# with the renderer where the Vulkan device is the same GPU, else uploaded; the log says which),
# `ocean bench` for both GPU backends at 256² and 512² with 4 cascades, and `ocean bench
# --overlap` (the cascades, the far field's 512² noise map and both, on the CPU, Vulkan and CUDA
# backends), writing JSON under $OUT (default ./gpu-check-out). Each step has its own time limit
# (together 470 s, under 8 minutes); a failing step is recorded and the next one runs.
#   OUT=/some/folder tools/gpu-check.sh
#   BUILD=build/gpu-check tools/gpu-check.sh --build-only   # prepare on a machine with nvcc
# Without nvcc on the GPU machine, carry a build folder prepared with --build-only (ocean and
# conformance_tests, render_tests: the CUDA runtime is linked in, cuFFT loaded where present, else
# the backend's own FFT kernels run) and point BUILD at it: configure and build are then skipped.
# Environment: OUT; BUILD (default build/gpu-check; an existing build folder is reused as it is
# configured, e.g. BUILD=build/release); JOBS (default: all cores); CUDACXX or nvcc on PATH or in
# /usr/local/cuda/bin (without nvcc the CUDA steps report "built without CUDA").
# Writes: environment.json (nvidia-smi, nvcc, ocean info), build.log, conformance-{cuda,vulkan}.
# {json,log} and render-cuda.{json,log} (googletest's JSON), bench-{cuda,vulkan}.json,
# bench-overlap.json, summary.json (every step's exit status and seconds). Exit status: 0 when
# every step passed, 1 otherwise.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
out="$(mkdir -p "${OUT:-./gpu-check-out}" && cd "${OUT:-./gpu-check-out}" && pwd)"
build="${BUILD:-build/gpu-check}"
jobs="${JOBS:-$(nproc)}"
start=$SECONDS
steps=()

step() {  # step NAME LIMIT_S COMMAND...: runs the command under a time limit, records the result
  local name=$1 limit=$2; shift 2
  local t0=$SECONDS
  echo "gpu-check: $name (limit ${limit}s)" >&2
  timeout --kill-after=10 "$limit" "$@"
  local rc=$?
  steps+=("{\"step\": \"$name\", \"exit\": $rc, \"seconds\": $((SECONDS - t0))}")
  echo "gpu-check: $name: exit $rc after $((SECONDS - t0)) s" >&2
  return $rc
}

# nvcc: CUDACXX, PATH, or the toolkit's usual place.
if [[ -z "${CUDACXX:-}" ]]; then
  if command -v nvcc > /dev/null; then CUDACXX=$(command -v nvcc)
  elif [[ -x /usr/local/cuda/bin/nvcc ]]; then CUDACXX=/usr/local/cuda/bin/nvcc
  fi
fi
cuda_flag=-DOCEAN_CUDA=OFF
if [[ -n "${CUDACXX:-}" ]]; then
  export CUDACXX
  cuda_flag=-DOCEAN_CUDA=ON
fi

environment() {
  {
    echo "{"
    echo "\"nvidia_smi\": $(nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm \
         --format=csv,noheader 2>&1 | python3 -c 'import json,sys; print(json.dumps(sys.stdin.read().strip()))'),"
    echo "\"nvcc\": $( ("${CUDACXX:-nvcc}" --version 2>&1 || echo "no nvcc") | tail -1 | python3 -c 'import json,sys; print(json.dumps(sys.stdin.read().strip()))'),"
    echo "\"cores\": $(nproc)"
    echo "}"
  } > "$out/environment.json"
}
environment

# Configure and build the two targets the checks run (the CUDA kernels for the GPU found, when
# nvidia-smi reports its compute capability; else the build's default list).
arch=$(nvidia-smi --query-gpu=compute_cap --format=csv,noheader 2>/dev/null | head -1 | tr -d '. ')
arch_flag=()
[[ "$arch" =~ ^[0-9]+$ ]] && arch_flag=(-DCMAKE_CUDA_ARCHITECTURES="$arch")
prebuilt=0
if [[ -z "${CUDACXX:-}" && -x "$build/apps/ocean/ocean" && -x "$build/tests/conformance_tests" \
      && -x "$build/tests/render_tests" && "${1:-}" != --build-only ]]; then
  prebuilt=1
  echo "gpu-check: no nvcc here: using the binaries in $build" >&2
elif [[ -f "$build/CMakeCache.txt" ]]; then
  step configure 40 cmake -S . -B "$build" > "$out/build.log" 2>&1
else
  step configure 40 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DOCEAN_BUILD_BENCH=OFF "$cuda_flag" "${arch_flag[@]}" > "$out/build.log" 2>&1
fi
((prebuilt)) || step build 200 cmake --build "$build" -j "$jobs" --target ocean_cli \
  conformance_tests render_tests >> "$out/build.log" 2>&1
if [[ "${1:-}" == --build-only ]]; then
  echo "gpu-check: built $build/apps/ocean/ocean, $build/tests/conformance_tests and" \
       "$build/tests/render_tests" >&2
  exit 0
fi
ocean="$build/apps/ocean/ocean"
if [[ -x "$ocean" ]]; then
  "$ocean" info --json > "$out/info.json" 2>&1
  "$ocean" info >&2
fi

# Conformance: every case of ocean/conformance.hpp against the CPU reference (cuda: on cuFFT and
# on the own FFT kernels, "cuda_kernels"). OCEAN_REQUIRE_CUDA
# turns a missing CUDA device into a failure (it only skips elsewhere).
for backend in cuda vulkan; do
  step "conformance-$backend" 45 env OCEAN_REQUIRE_CUDA=1 OCEAN_REQUIRE_DEVICES=1 \
    "$build/tests/conformance_tests" --gtest_filter="*/$backend*" \
    --gtest_output="json:$out/conformance-$backend.json" > "$out/conformance-$backend.log" 2>&1
done

# The CUDA backend's frames rendered (shared with the renderer, or uploaded) against the CPU
# backend's picture (tests/render/scene_test.cpp); the log's "cuda scene:" line says which path.
step render-cuda 35 env OCEAN_REQUIRE_CUDA=1 OCEAN_REQUIRE_DEVICES=1 "$build/tests/render_tests" \
  --gtest_filter="Scene.Cuda*:SharedInputs.*" --gtest_output="json:$out/render-cuda.json" \
  > "$out/render-cuda.log" 2>&1

# GPU time per frame at 256² and 512², 4 cascades, every output.
for backend in cuda vulkan; do
  step "bench-$backend" 35 "$ocean" bench --backend "$backend" --resolution 256,512 \
    --cascades 4 --json > "$out/bench-$backend.json" 2> "$out/bench-$backend.log"
done

# the concurrent kernels of [VR-GIS FFT+Perlin]: the cascades alone, the far field's noise map alone and both in
# one frame (CUDA: the map on its own stream in the frame's graph, GPU time; CPU and Vulkan: wall
# time), 4 cascades at 256² and 512², a 512² map; overlap = (t_c + t_n − t_both)/min(t_c, t_n).
step bench-overlap 35 "$ocean" bench --overlap --resolution 256,512 --cascades 4 \
  --far-noise-resolution 512 --min-time 0.3 --json > "$out/bench-overlap.json" \
  2> "$out/bench-overlap.log"

failed=0
for s in "${steps[@]}"; do [[ "$s" == *'"exit": 0,'* ]] || failed=1; done
{
  echo "{\"seconds\": $((SECONDS - start)), \"pass\": $([[ $failed == 0 ]] && echo true || echo false), \"steps\": ["
  (IFS=,; echo "${steps[*]}")
  echo "]}"
} > "$out/summary.json"
cat "$out/summary.json"
exit $failed
