#!/usr/bin/env bash
# Never freeze the UI (issue 15 item 6): a slow technique (virtual-tiled: seconds a frame on
# llvmpipe) takes more than the 250 ms budget, so the view renders at 1/2..1/8 of its size
# and says so in the view; a large budget climbs back; view.adaptive off renders full size.
# usage: adaptive_resolution.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/adaptive_resolution
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 400 "$app" --scene default --technique virtual-tiled --self-test "adaptive-resolution=$out" \
  >"$out/adaptive.stdout" 2>"$out/adaptive.stderr" || rc=$?
cat "$out/adaptive.stdout"
if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/adaptive.stdout"; then
  echo "FAIL: self-test adaptive-resolution exited with $rc; stderr:"
  cat "$out/adaptive.stderr"
  exit 1
fi
echo "PASS"
