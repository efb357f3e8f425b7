#!/usr/bin/env bash
# Runs the `ocean` tool on hostile and careless inputs and prints one table row per case: the
# exit status, the number of lines and bytes on standard error, and whether anything unexpected
# happened (a signal, a sanitizer report, more than one line, a long line, files left behind).
#   tools/hostile-inputs.sh [path/to/ocean]      (default build/release/apps/ocean/ocean)
# Every case runs in a fresh scratch folder; nothing outside it is written.
set -uo pipefail
ocean=$(realpath "${1:-build/release/apps/ocean/ocean}")
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
big=$(head -c 120000 /dev/zero | tr '\0' 'x')
deep=$(python3 -c 'print("{\"a\":" * 50000 + "1" + "}" * 50000)')

printf '| case | exit | stderr lines | stderr bytes | verdict | message |\n|---|---|---|---|---|---|\n'
n=0
run() {  # run "description" expected-files-glob-or-- command...
  local what=$1 expect=$2; shift 2
  n=$((n + 1))
  local dir="$root/$n"; mkdir -p "$dir"; cd "$dir" || exit 1
  mknod device c 1 3 2>/dev/null; mknod device.png c 1 3 2>/dev/null || true   # a private copy of /dev/null's node
  mkfifo fifo fifo.png
  printf '%s' "$deep" > deep.json
  if declare -F "$1" > /dev/null; then "$@"; else timeout 120 "$@"; fi > stdout 2> stderr < /dev/null
  local rc=$? lines bytes verdict=ok
  lines=$(wc -l < stderr); bytes=$(wc -c < stderr)
  # 130 and 143: the tool's own exit after SIGINT or SIGTERM (128 + the signal), by design.
  if ((rc == 124)); then verdict="TIMEOUT"; fi
  if ((rc > 128 && rc != 130 && rc != 143)); then verdict="SIGNAL $((rc - 128))"; fi
  grep -q "Sanitizer\|runtime error\|terminate called\|Aborted" stderr && verdict="CRASH REPORT"
  grep -qiw "nan\|inf\|-nan\|-inf" stdout && verdict="NAN/INF PRINTED"
  ((lines > 1 && rc != 0)) && [[ $verdict == ok ]] && verdict="more than one line"
  ((bytes > 400)) && [[ $verdict == ok ]] && verdict="long message"
  [[ -c device && -c device.png ]] || verdict="DEVICE NODE REPLACED"
  [[ -p fifo && -p fifo.png ]] || verdict="FIFO REPLACED"
  [[ -n $(find . -name '*.tmp*' | head -1) ]] && verdict="$verdict; TEMPORARY LEFT"
  local left
  left=$(find . -mindepth 1 -not -name stdout -not -name stderr -not -name device -not -name device.png -not -name fifo -not -name fifo.png \
         -not -name deep.json ${expect:+-not -path "./$expect"} -not -path "./$expect/*" | head -3 | tr '\n' ' ')
  [[ -n $left ]] && verdict="$verdict; left: $left"
  ((rc == 0)) && [[ $expect == -- ]] && verdict="$verdict; exit 0"
  local first
  first=$(head -n 1 stderr | cut -c 1-90 | tr '|' '/')
  printf '| %s | %d | %d | %d | %s | %s |\n' "$what" "$rc" "$lines" "$bytes" "$verdict" "$first"
  cd "$root" || exit 1
}
o=$ocean
run "spectrum --hs -3" -- $o spectrum --hs -3 --tp 8 --omega 0.5,1
run "spectrum --hs nan" -- $o spectrum --hs nan --tp 8 --omega 0.5,1
run "spectrum --tp 1e400" -- $o spectrum --hs 2 --tp 1e400 --omega 0.5,1
run "spectrum 120 kB number" -- $o spectrum --hs "$big" --tp 8 --omega 0.5,1
run "spectrum --json > /dev/full" -- sh -c "$o spectrum --hs 2 --tp 8 --omega 1 --json > /dev/full"
run "dispersion --omega 1e20 capillary" -- $o dispersion --omega 1e20 --capillary
run "dispersion --k 1e308" -- $o dispersion --k 1e308
run "dispersion --omega 1e-300" -- $o dispersion --omega 1e-300
run "preset /dev/zero" -- $o stats --seeds 1 --resolution 32 --preset /dev/zero
run "preset fifo" -- $o stats --seeds 1 --resolution 32 --preset fifo
run "preset 50 000 deep" -- $o stats --seeds 1 --resolution 32 --preset deep.json
run "preset directory" -- $o stats --seeds 1 --resolution 32 --preset .
run "--set 120 kB value" -- $o stats --seeds 1 --resolution 32 --set "sea.wind_sea.fetch_m=$big"
run "--set no equals" -- $o stats --seeds 1 --resolution 32 --set sea
run "resolution 1000" -- $o stats --seeds 1 --resolution 1000
run "resolution 1e9" -- $o stats --seeds 1 --resolution 1073741824
run "loop period 1e-9" -- $o stats --seeds 1 --resolution 32 --loop-period 1e-9
run "render 16384x16384" -- $o render --width 16384 --height 16384 --out big.png
run "render --out %s%n" -- $o render --width 32 --height 24 --frames 2 --out 'a%s%n.png'
run "render --out two %05d" -- $o render --width 32 --height 24 --frames 2 --out 'a%05d_%05d.png'
run "render --out quote" "it's \"q\"*" $o render --width 32 --height 24 --out "it's \"q\".png"
run "render --out \$(touch pwned)" '$(touch pwned)*' $o render --width 32 --height 24 --out '$(touch pwned).png'
run "render mp4 with quote" "a'b.mp4" $o render --width 32 --height 24 --frames 3 --out "a'b.mp4"
run "render --out newline" "$(printf 'a\nb')*" $o render --width 32 --height 24 --out "$(printf 'a\nb.png')"
run "render --out non-UTF-8" "$(printf 'a\xffb')*" $o render --width 32 --height 24 --out "$(printf 'a\xffb.png')"
run "render --out device" -- $o render --width 32 --height 24 --out device.png
run "render --out fifo" -- $o render --width 32 --height 24 --out fifo.png
run "render --out directory" -- $o render --width 32 --height 24 --out .
run "render --out missing folder" -- $o render --width 32 --height 24 --out no/such/a.png
run "spectrum --plot device" -- $o spectrum --plot device.png
run "bake --out device" -- $o bake --frames 1 --resolution 16 --out device.png
run "bake --contact-sheet bad folder" -- $o bake --frames 2 --resolution 16 --out b --contact-sheet no/such/s.png
run "bake --resolution 100" -- $o bake --frames 1 --resolution 100 --out b
run "bake --frames -1" -- $o bake --frames -1 --out b
run "lod --out device" -- $o lod --camera 0,10,0 --target 0,0,100 --out device.png
run "lod --png fifo" -- $o lod --camera 0,10,0 --target 0,0,100 --png fifo.png
run "spectrum --omega 1e-300" -- $o spectrum --hs 2 --tp 8 --omega 1e-300
# A background job of a non-interactive shell ignores SIGINT: python sends the signals instead.
interrupt() {  # interrupt SIGNAL: a bake signalled once its first frames are written
  python3 - "$o" "$1" <<'PY'
import signal, subprocess, sys, time
p = subprocess.Popen([sys.argv[1], "bake", "--frames", "400", "--resolution", "64", "--out", "b"])
time.sleep(3)
p.send_signal(getattr(signal, sys.argv[2]))
rc = p.wait()
sys.exit(128 - rc if rc < 0 else rc)
PY
}
run "bake SIGINT mid-bake" b interrupt SIGINT
run "bake SIGTERM mid-bake" b interrupt SIGTERM
run "two bakes, one folder" b sh -c "$o bake --frames 60 --resolution 64 --out b --seed 1 2>/dev/null & sleep 1; $o bake --frames 5 --resolution 64 --seed 2 --out b; r=\$?; wait; exit \$r"
run "bake, file size limit 64 kB" b sh -c "ulimit -f 64; $o bake --frames 5 --resolution 64 --out b"
run "unknown subcommand" -- $o paint
run "unknown subcommand with a newline" -- $o "$(printf 'pa\nint')"
run "bake --out with a newline, missing folder" no $o bake --frames 1 --resolution 16 --out "$(printf 'no/such\nfolder')"
run "bake --out existing file" f sh -c "touch f && $o bake --frames 1 --resolution 16 --out f"
run "bake --out unwritable folder (uid 65534)" ro sh -c "mkdir ro && chmod 555 ro && setpriv --reuid=65534 --regid=65534 --clear-groups $o bake --frames 1 --resolution 16 --out ro/b"
run "bake --resolution 1e9 cascades 50" -- $o bake --frames 1 --resolution 1073741824 --cascades 50 --out b
run "stats --threads -1" -- $o stats --seeds 1 --resolution 32 --threads -1
run "bench --resolution 0" -- $o bench --resolution 0
run "validate --backend nosuch" -- $o validate --backend nosuch
run "info with stdout closed" -- sh -c "$o info >&-"
printf '\n%d cases; scratch folder %s removed.\n' "$n" "$root"
