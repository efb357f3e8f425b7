#!/usr/bin/env bash
# Runs one fuzz target for a fixed time over its committed seeds and fails on any finding.
#   tests/fuzz/run.sh FUZZER NAME [SECONDS] [libFuzzer flags...]
# FUZZER is the built target (build/fuzz/tests/fuzz/NAME_fuzz), NAME picks corpus/NAME/ and the
# dictionary NAME.dict next to this script. New inputs go to a temporary directory (the committed
# corpus is read, never written) that is removed at the end, or to $OCEAN_FUZZ_KEEP when set.
# A finding is written to ./artifacts/NAME/ (crash-<sha1>, leak-..., timeout-..., oom-...).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
fuzzer="$1" name="$2" seconds="${3:-20}"
shift $(($# < 3 ? $# : 3))

corpus="$here/corpus/$name"
[[ -d "$corpus" ]] || { echo "run.sh: no seed corpus $corpus" >&2; exit 2; }
if [[ -n "${OCEAN_FUZZ_KEEP:-}" ]]; then
  work="$OCEAN_FUZZ_KEEP"
  mkdir -p "$work"
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/ocean-fuzz-$name.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi
artifacts="artifacts/$name"
mkdir -p "$artifacts"
flags=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096
       -print_final_stats=1 -artifact_prefix="$artifacts/")
[[ -f "$here/$name.dict" ]] && flags+=(-dict="$here/$name.dict")

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
# libFuzzer writes new inputs to the first directory only: the seeds are the second.
status=0
"$fuzzer" "${flags[@]}" "$@" "$work" "$corpus" || status=$?
if ((status != 0)); then
  echo "run.sh: ${name}_fuzz failed (exit $status); the input is in $PWD/$artifacts/;" \
       "reproduce with: $fuzzer $PWD/$artifacts/<file>" >&2
fi
exit "$status"
