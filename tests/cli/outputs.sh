#!/usr/bin/env bash
# shadowlab-cli output files (issue 14, lost work): outputs are checked before the work
# starts (two options naming one file, a folder that cannot be made or written, a folder
# given as a file: exit 2 naming the option(s), nothing written); writes are atomic (no
# temporary file left behind, an existing file replaced whole); a write error after the work
# (/dev/full) exits 1 naming the file.
set -uo pipefail
cli=$1 out=$3/outputs
rm -rf "$out"
mkdir -p "$out"
fail=0
# check RC "exact last stderr line" args...: the exit status and the message (the last line
# of stderr: bench prints progress before a write error).
check() {
  local want_rc=$1 want=$2; shift 2
  local err rc=0 start=$SECONDS
  err=$("$cli" "$@" 2>&1 >/dev/null) || rc=$?
  local last=${err##*$'\n'}
  if [ $rc -ne "$want_rc" ]; then
    echo "FAIL (exit $rc, expected $want_rc): $* said: $err"; fail=1; return
  fi
  if [ "$last" != "$want" ]; then
    echo "FAIL: '$*'"; echo "  said:     '$last'"; echo "  expected: '$want'"; fail=1; return
  fi
  echo "ok ($((SECONDS - start)) s): $last"
}
tiny=(--size 64x36)
render=(render --scene plane-box --technique uniform "${tiny[@]}")
bench=(bench --scene plane-box --technique uniform:resolution=64 --frames 1 --warmup 0 "${tiny[@]}")

# Two options naming one file: refused before any work, the file is not created.
check 2 "shadowlab-cli: --chart: '$out/same' is the same file as --csv (one would overwrite the other)" \
  "${bench[@]}" --csv "$out/same" --chart "$out/same"
check 2 "shadowlab-cli: --metrics: '$out/./a.png' is the same file as --out (one would overwrite the other)" \
  "${render[@]}" --out "$out/a.png" --metrics "$out/./a.png"
check 2 "shadowlab-cli: --error-image: '$out/a.png' is the same file as --out (one would overwrite the other)" \
  "${render[@]}" --out "$out/a.png" --error-image "$out/a.png"
if [ -e "$out/same" ] || [ -e "$out/a.png" ]; then echo "FAIL: a refused run wrote a file"; fail=1; fi

# chart: the PNG must not overwrite its input CSV.
"$cli" "${bench[@]}" --csv "$out/in.csv" >/dev/null 2>&1 || { echo "FAIL: bench"; fail=1; }
cp "$out/in.csv" "$out/in.csv.orig"
check 2 "shadowlab-cli: --chart: '$out/in.csv' is the same file as --csv (the input would be overwritten)" \
  chart --csv "$out/in.csv" --chart "$out/in.csv"
cmp -s "$out/in.csv" "$out/in.csv.orig" || { echo "FAIL: chart changed its input"; fail=1; }

# A folder that cannot be created or written, or a folder given as a file: before rendering.
: >"$out/plain-file"
check 2 "shadowlab-cli: --out: cannot create the folder '$out/plain-file/sub' (Not a directory)" \
  "${render[@]}" --out "$out/plain-file/sub/x.png"
check 2 "shadowlab-cli: --csv: cannot write in the folder '/proc' (No such file or directory)" \
  "${bench[@]}" --csv /proc/x.csv
check 2 "shadowlab-cli: --csv: cannot create the folder '/proc/shadowlab-nope' (No such file or directory)" \
  "${bench[@]}" --csv /proc/shadowlab-nope/x.csv
check 2 "shadowlab-cli: --json: cannot create the folder '/proc/shadowlab-nope' (No such file or directory)" \
  stability --scene plane-box --technique uniform --frames 1 "${tiny[@]}" \
  --json /proc/shadowlab-nope/x.json
check 2 "shadowlab-cli: --metrics: '$out' is a folder" \
  "${render[@]}" --out "$out/b.png" --metrics "$out"
check 2 "shadowlab-cli: --out-dir: cannot create the folder '$out/plain-file' (Not a directory)" \
  compare --scene plane-box "${tiny[@]}" --out-dir "$out/plain-file"
if [ "$(id -u)" -ne 0 ]; then  # root writes anywhere
  mkdir -p "$out/read-only" && chmod 555 "$out/read-only"
  check 2 "shadowlab-cli: --out: cannot write in the folder '$out/read-only' (Permission denied)" \
    "${render[@]}" --out "$out/read-only/x.png"
fi

# A write error after the work is exit 1 naming the file, not exit 0.
check 1 "shadowlab-cli: /dev/full: cannot write (No space left on device)" \
  "${bench[@]}" --csv /dev/full
check 1 "shadowlab-cli: /dev/full: cannot write (No space left on device)" \
  "${render[@]}" --out "$out/c.png" --metrics /dev/full
# A device is written in place (not replaced by a rename): /dev/null stays a device.
"$cli" "${render[@]}" --out "$out/d.png" --metrics /dev/null >/dev/null || {
  echo "FAIL: --metrics /dev/null"; fail=1; }
test -c /dev/null || { echo "FAIL: /dev/null is no longer a device"; fail=1; }

# Atomic: an existing file is replaced whole and no temporary file is left behind.
echo old >"$out/e.json"
"$cli" "${render[@]}" --out "$out/e.png" --metrics "$out/e.json" >/dev/null || {
  echo "FAIL: render"; fail=1; }
python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$out/e.json" || {
  echo "FAIL: e.json is not the new metrics"; fail=1; }
leftover=$(find "$out" -name '.*tmp*' -o -name '.shadowlab-probe-*')
[ -z "$leftover" ] || { echo "FAIL: temporary files left: $leftover"; fail=1; }
exit $fail
