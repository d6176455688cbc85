#!/usr/bin/env bash
# The GUI starts on the default scene with the uniform technique, renders 5 frames and
# saves the window, the viewport and each panel; the window image must be a real picture.
# usage: grab_default.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_default
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 300 "$app" --scene default --technique uniform --grab "$out" --grab-after 5 \
  >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
cat "$out/stdout.txt"
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab exited with $rc; stderr:"
  cat "$out/stderr.txt"
  exit 1
fi
for f in window.png viewport.png panel-parameters.png panel-timing.png; do
  [[ -s "$out/$f" ]] || { echo "FAIL: $out/$f missing"; exit 1; }
  grep -qF "$out/$f" "$out/stdout.txt" || { echo "FAIL: $f not printed on stdout"; exit 1; }
done
# Not blank: many colours and real contrast, at (nearly) the requested window size.
python3 "$here/pngstats.py" --min-colors 64 --min-stddev 8 --min-size 1200x800 "$out/window.png"
python3 "$here/pngstats.py" --min-colors 32 --min-stddev 8 --min-size 640x480 "$out/viewport.png"
echo "PASS"
