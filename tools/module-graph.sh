#!/usr/bin/env bash
# Draws the module graph of the project as CMake sees it: `cmake --graphviz` on a configured
# build, filtered to the project's own targets (the ocean_* libraries and the ocean_cli
# executable; tests, benchmarks and the ocean::ocean umbrella left out), their direct external
# packages in grey (C runtime libraries such as m, dl and Threads left out), rendered with
# graphviz's dot into docs/images/modules.svg and docs/images/modules.png.
#
# Usage: tools/module-graph.sh [--build DIR] [--out DIR] [--no-external]
#   --build DIR     a configured build tree (default: build/release if configured, else a
#                   temporary configuration that is removed afterwards)
#   --out DIR       where modules.svg/.png go (default: docs/images)
#   --no-external   only the project's own targets
# Edges point from a target to what it links: solid PUBLIC, dashed PRIVATE, dotted INTERFACE.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=""
out="$root/docs/images"
external=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build="${2:?--build needs a directory}"; shift 2 ;;
    --out) out="${2:?--out needs a directory}"; shift 2 ;;
    --no-external) external=0; shift ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "module-graph: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

for tool in cmake dot; do
  if ! command -v "$tool" > /dev/null; then
    case "$tool" in
      dot) echo "module-graph: graphviz's dot not found: install graphviz (apt-get install graphviz)" >&2 ;;
      *) echo "module-graph: cmake not found: install cmake (apt-get install cmake)" >&2 ;;
    esac
    exit 1
  fi
done

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

if [[ -z "$build" && -f "$root/build/release/CMakeCache.txt" ]]; then
  build="$root/build/release"
fi
if [[ -n "$build" ]]; then
  [[ -f "$build/CMakeCache.txt" ]] || { echo "module-graph: $build is not a configured build tree" >&2; exit 1; }
  cmake --graphviz="$tmp/graph/ocean.dot" "$build" > "$tmp/cmake.log" 2>&1 ||
    { cat "$tmp/cmake.log" >&2; exit 1; }
else
  cmake -S "$root" -B "$tmp/build" -DOCEAN_BUILD_TESTS=OFF -DOCEAN_BUILD_BENCH=OFF \
    --graphviz="$tmp/graph/ocean.dot" > "$tmp/cmake.log" 2>&1 ||
    { cat "$tmp/cmake.log" >&2; exit 1; }
fi

# CMake's file: `"nodeN" [ label = "name\n(alias)", shape = S ];` and
# `"nodeA" -> "nodeB" [ style = dashed|dotted ] // a -> b` (no style = PUBLIC).
awk -v external="$external" '
function own(name) { return name ~ /^ocean_/ }
function system_lib(name) { return name ~ /^(m|dl|rt|pthread|Threads::Threads)$/ }
function umbrella(name) { return name == "ocean" }  # ocean::ocean links every module
function short(name) {  # /usr/lib/x86_64-linux-gnu/libimgui.a -> imgui, PkgConfig::OCEAN_IMGUI -> imgui
  if (name ~ /\//) { sub(/.*\//, "", name); sub(/^lib/, "", name); sub(/\.(a|so).*$/, "", name) }
  if (name ~ /^PkgConfig::/) { sub(/^PkgConfig::(OCEAN_)?/, "", name); name = tolower(name) }
  return name
}
/^ *"node[0-9]+" \[ label = / {
  id = $1; gsub(/"/, "", id)
  line = $0
  sub(/.*label = "/, "", line); name = line; sub(/(\\n|").*/, "", name)
  shape = $0; sub(/.*shape = /, "", shape); sub(/ .*/, "", shape)
  label[id] = name; kind[id] = shape
  next
}
/^ *"node[0-9]+" -> "node[0-9]+"/ {
  a = $1; b = $3; gsub(/"/, "", a); gsub(/"/, "", b)
  style = "solid"
  if ($0 ~ /style = dashed/) style = "dotted"    # CMake: dashed = INTERFACE
  if ($0 ~ /style = dotted/) style = "dashed"    # CMake: dotted = PRIVATE
  n++; from[n] = a; to[n] = b; how[n] = style
}
END {
  print "digraph modules {"
  print "  graph [rankdir = TB, nodesep = 0.25, ranksep = 0.55, fontname = \"DejaVu Sans\", fontsize = 10,"
  print "         labelloc = b, label = \"edges point to what a target links: solid PUBLIC, dashed PRIVATE, dotted INTERFACE; grey: external packages\"];"
  print "  node [fontname = \"DejaVu Sans\", fontsize = 11, shape = box, style = \"rounded,filled\","
  print "        color = \"#3b6ea5\", fillcolor = \"#dde9f6\"];"
  print "  edge [color = \"#3b6ea5\", arrowsize = 0.6];"
  for (id in label) {
    if (!own(label[id])) continue
    if (kind[id] == "egg")
      printf "  \"%s\" [fillcolor = \"#f6e3c6\", color = \"#a5743b\", style = \"rounded,filled,bold\"];\n", label[id]
    else
      printf "  \"%s\";\n", label[id]
  }
  for (i = 1; i <= n; i++) {
    a = from[i]; b = to[i]
    if (!own(label[a])) continue
    if (own(label[b])) {
      key = label[a] SUBSEP label[b]
      if (!(key in seen)) { seen[key] = 1; printf "  \"%s\" -> \"%s\" [style = %s];\n", label[a], label[b], how[i] }
    } else if (external && !system_lib(label[b]) && !umbrella(label[b])) {
      ext = short(label[b])
      if (!(ext in shown)) {
        shown[ext] = 1
        printf "  \"%s\" [fillcolor = \"#f2f2f2\", color = \"#a0a0a0\", fontcolor = \"#707070\", fontsize = 9];\n", ext
      }
      key = label[a] SUBSEP ext
      if (!(key in seen)) { seen[key] = 1; printf "  \"%s\" -> \"%s\" [style = %s, color = \"#b0b0b0\"];\n", label[a], ext, how[i] }
    }
  }
  print "}"
}' "$tmp/graph/ocean.dot" > "$tmp/modules.dot"

grep -q ' -> ' "$tmp/modules.dot" || { echo "module-graph: no ocean_* targets in the CMake graph" >&2; exit 1; }
mkdir -p "$out"
dot -Tsvg "$tmp/modules.dot" -o "$out/modules.svg"
dot -Tpng -Gdpi=110 "$tmp/modules.dot" -o "$out/modules.png"
echo "module-graph: wrote $out/modules.svg and $out/modules.png"
