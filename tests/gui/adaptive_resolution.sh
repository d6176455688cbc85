#!/usr/bin/env bash
# Adaptive resolution a lecturer can trust: off by default; turned on, a slow technique
# (virtual-tiled: seconds a frame on llvmpipe) drops the view to half its size and never
# lower, and the view says so; an export is the full-size image, and so is a grab of the
# reduced view; a still view is redrawn at full size; a fast technique returns to full size
# within one second (the test prints recovery_ms); view.adaptive off renders full size;
# presenter mode and the split view turn it off until they end, opening a lesson for good.
# usage: adaptive_resolution.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/adaptive_resolution
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test adaptive-resolution" 400 "$out/adaptive" \
  "$tests" --scene default --technique virtual-tiled --test "adaptive-resolution=$out"
echo "PASS"
