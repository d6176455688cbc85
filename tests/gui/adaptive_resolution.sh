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

run_self_test "self-test adaptive-resolution" 400 "$out/adaptive" \
  "$app" --scene default --technique virtual-tiled --self-test "adaptive-resolution=$out"
echo "PASS"
