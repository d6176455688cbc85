#!/usr/bin/env bash
# scripts/rtw-regrid-noise.sh under the output policy, with a stub shadowlab-cli: a view's log
# that links to the scene file and a CSV that is a FIFO are refused in one line (exit 2) before
# the first render, the scene untouched; a good run leaves its logs and no temporary file.
# usage: rtw_regrid_noise.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_regrid_noise"
export SHADOWLAB_CLI=$stub_cli

expect_link_refused "a log links to the scene" "$box/out/regrid-room@1-64.log" "$scene" \
  "the log '$box/out/regrid-room@1-64.log' is the same file as the scene '$box/scenes/room.gltf'" \
  root/scripts/rtw-regrid-noise.sh "$box/out" 64 "$box/scenes/room.gltf"

rm -f "$box/out/regrid-room@7-64.csv" && mkfifo "$box/out/regrid-room@7-64.csv"
expect_refused "a CSV is a FIFO" "'$box/out/regrid-room@7-64.csv' is a FIFO, not a regular file" \
  root/scripts/rtw-regrid-noise.sh "$box/out" 64 "$box/scenes/room.gltf"
rm "$box/out/regrid-room@7-64.csv"

expect_good_run "a good run" "$box/out/regrid-room@7-64.log" "stub bench output" \
  root/scripts/rtw-regrid-noise.sh "$box/out" 64 "$box/scenes/room.gltf"
finish
