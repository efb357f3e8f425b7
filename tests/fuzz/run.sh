#!/usr/bin/env bash
# Runs one fuzz target in one of three modes and fails on any finding.
#   tests/fuzz/run.sh replay FUZZER NAME                 every committed input once
#   tests/fuzz/run.sh smoke  FUZZER NAME RUNS SEED [CAP] RUNS inputs from a fixed seed
#   tests/fuzz/run.sh random FUZZER NAME SECONDS [libFuzzer flags...]
# FUZZER is the built target (build/fuzz/tests/fuzz/NAME_fuzz); NAME picks corpus/NAME/ (the
# seeds), regressions/NAME/ (every input a target ever failed on: crash, leak, timeout and oom
# files) and the dictionary NAME.dict next to this script.
#  - replay runs each committed input (seeds and regressions) exactly once: nothing random.
#  - smoke (what `./dev test` runs) starts from the same inputs, then mutates with the fixed
#    SEED for exactly RUNS executions, with no corpus reloads on the clock and no address-space
#    randomisation, so every run tries the same inputs; CAP seconds (default 300) bound a run on
#    a machine far slower than expected, and a capped run says so.
#  - random (what `./dev fuzz` runs) uses a seed from the clock for SECONDS and writes what it
#    finds into regressions/NAME/, to be committed with the fix that makes it pass.
# New inputs go to a temporary directory (the committed directories are read, never written),
# removed at the end, or to $OCEAN_FUZZ_KEEP when set. A finding of replay and smoke goes to
# ./artifacts/NAME/ (crash-<sha1>, leak-..., timeout-..., oom-...).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
usage() {
  echo "usage: run.sh replay FUZZER NAME | smoke FUZZER NAME RUNS SEED [CAP] |" \
       "random FUZZER NAME SECONDS [flags...]" >&2
  exit 2
}
(($# >= 3)) || usage
mode="$1" fuzzer="$2" name="$3"
shift 3

corpus="$here/corpus/$name"
regressions="$here/regressions/$name"
[[ -d "$corpus" ]] || { echo "run.sh: no seed corpus $corpus" >&2; exit 2; }
inputs=("$corpus")
[[ -d "$regressions" ]] && inputs+=("$regressions")

if [[ -n "${OCEAN_FUZZ_KEEP:-}" ]]; then
  work="$OCEAN_FUZZ_KEEP"
  mkdir -p "$work"
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/ocean-fuzz-$name.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi
artifacts="$PWD/artifacts/$name"
flags=(-timeout=10 -rss_limit_mb=2048 -print_final_stats=1)
[[ -f "$here/$name.dict" ]] && flags+=(-dict="$here/$name.dict")
case "$mode" in
  replay)
    # -runs=0: read and execute every input of the directories, mutate nothing. No -max_len, so
    # each input runs whole.
    flags+=(-runs=0)
    ;;
  smoke)
    (($# >= 2)) || usage
    runs="$1" seed="$2" cap="${3:-300}"
    # -reload=0: libFuzzer otherwise rereads its corpus directory every second, so what it
    # mutates next would depend on the clock.
    flags+=(-runs="$runs" -seed="$seed" -max_total_time="$cap" -max_len=4096 -reload=0 -use_cmp=0)
    ;;
  random)
    (($# >= 1)) || usage
    seconds="$1"
    shift
    artifacts="$regressions"
    flags+=(-max_total_time="$seconds" -max_len=4096 "$@")
    ;;
  *) usage ;;
esac
mkdir -p "$artifacts"
flags+=(-artifact_prefix="$artifacts/")

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
# libFuzzer writes new inputs to the first directory only: the committed ones come after it.
# Without address-space randomisation where the machine allows it (setarch -R): libFuzzer keys
# its table of recent comparisons by the code's addresses, whose mutations would otherwise differ
# from run to run.
launch=()
if [[ "$mode" != random ]] && setarch "$(uname -m)" -R true 2>/dev/null; then
  launch=(setarch "$(uname -m)" -R)
fi
log="$(mktemp "${TMPDIR:-/tmp}/ocean-fuzz-$name-log.XXXXXX")"
status=0
"${launch[@]}" "$fuzzer" "${flags[@]}" "$work" "${inputs[@]}" 2>&1 | tee "$log" >&2 ||
  status=${PIPESTATUS[0]}
if [[ "$mode" == smoke ]] && grep -q "^Done .* in [0-9]* second" "$log" &&
   ! grep -q "^Done $runs runs" "$log"; then
  echo "run.sh: ${name}_fuzz stopped at its $cap s cap before $runs runs" >&2
fi
rm -f "$log"
if ((status != 0)); then
  echo "run.sh: ${name}_fuzz failed in $mode mode (exit $status); the input is in $artifacts/;" \
       "reproduce with: $fuzzer $artifacts/<file>" >&2
  [[ "$mode" == random ]] &&
    echo "run.sh: commit it with the fix: git add $regressions" >&2
fi
exit "$status"
