#!/usr/bin/env bash
# scripts/rtw-turns.sh under the output policy, with a stub shadowlab-cli: a view's log that
# links to the scene file, a prediction that is a FIFO and an output folder that is a file are
# refused in one line (exit 2) before the first render, the scene untouched; a good run
# leaves its logs and no temporary file.
# usage: rtw_turns.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_turns"
export SHADOWLAB_CLI=$stub_cli

expect_link_refused "a log links to the scene" "$box/out/turns-room@3-64.log" "$scene" \
  "the log '$box/out/turns-room@3-64.log' is the same file as the scene '$box/scenes/room.gltf'" \
  root/scripts/rtw-turns.sh "$box/out" 64 "$box/scenes/room.gltf"

rm -f "$box/out/prediction-room@path-64-pixels.json"
mkfifo "$box/out/prediction-room@path-64-pixels.json"
expect_refused "a prediction is a FIFO" \
  "'$box/out/prediction-room@path-64-pixels.json' is a FIFO, not a regular file" \
  root/scripts/rtw-turns.sh "$box/out" 64 "$box/scenes/room.gltf"
rm "$box/out/prediction-room@path-64-pixels.json"

echo "not a folder" >"$box/file"
expect_refused "the output folder is a file" "OUTDIR '$box/file' is not a folder" \
  root/scripts/rtw-turns.sh "$box/file" 64 "$box/scenes/room.gltf@0"

expect_good_run "a good run" "$box/out/turns-room@0-64.log" "stub bench output" \
  root/scripts/rtw-turns.sh "$box/out" 64 "$box/scenes/room.gltf@0"
finish
