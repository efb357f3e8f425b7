#!/usr/bin/env bash
# web/build.sh [OUT_DIR] — builds the page into OUT_DIR (default build/web): the WebAssembly core
# with Debian's emscripten (into build/wasm, incremental) and the page's files beside it.
# Workarounds for Debian's emscripten 3.1.6 with Node 20: docs/web.md.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/build/web}"
wasm="$root/build/wasm"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}" EMSDK_PYTHON="${EMSDK_PYTHON:-/usr/bin/python3}"
if ! command -v emcmake >/dev/null; then
  # ctest reads 77 as "skipped"; OCEAN_REQUIRE_DEVICES=1 turns a missing toolchain into a failure.
  echo "web: emscripten is not installed (apt-get install emscripten; ./dev installs it)" >&2
  [[ "${OCEAN_REQUIRE_DEVICES:-0}" == 1 ]] && exit 1 || exit 77
fi
if [[ ! -f "$wasm/build.ninja" ]]; then
  emcmake cmake -S "$root/web/wasm" -B "$wasm" -G Ninja \
    -DCMAKE_CROSSCOMPILING_EMULATOR=/usr/bin/node >/dev/null
fi
cmake --build "$wasm" -j2 --target ocean_core spectrum_tests_wasm >/dev/null
mkdir -p "$out/shaders"
cp "$root/web/index.html" "$root"/web/src/*.js "$wasm/ocean_core.mjs" "$out/"
cp "$root"/web/src/shaders/*.wgsl "$out/shaders/"
