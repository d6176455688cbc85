#!/usr/bin/env bash
# The window never waits on the renderer: fvsm, virtual-tiled and da-rtw render continuously,
# still and while the camera is dragged, and a 10 ms heartbeat timer on the UI thread never
# stalls 100 ms (the figures are printed: "measure heartbeat ..."). The render service keeps
# every GL call, trace and readback on its own thread (docs/ARCHITECTURE.md).
# usage: heartbeat.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
tests=$4
out=$3/heartbeat
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test heartbeat" 900 "$out/heartbeat" \
  "$tests" --scene default --technique da-rtw --test "heartbeat=$out"
echo "PASS"
