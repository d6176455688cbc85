#!/usr/bin/env bash
# scripts/rtw-turns.sh under the output policy, with a stub shadowlab-cli: a view's log that
# links to the scene file, a prediction that is a FIFO and an output folder that is a file are
# refused in one line (exit 2) before the first render, the scene untouched; a good run
# leaves its logs and no temporary file.
# usage: rtw_turns.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_turns"
export SHADOWLAB_CLI=$stub_cli
mkdir -p "$box/scenes"
echo '{"asset": {"version": "2.0"}}' >"$box/scenes/room.gltf"

ln -s ../scenes/room.gltf "$box/out/turns-room@3-64.log"
expect_refused "a log links to the scene" \
  "the log '$box/out/turns-room@3-64.log' is the same file as the scene '$box/scenes/room.gltf'" \
  root/scripts/rtw-turns.sh "$box/out" 64 "$box/scenes/room.gltf"
expect_content "a log links to the scene" "$box/scenes/room.gltf" '{"asset": {"version": "2.0"}}'
rm "$box/out/turns-room@3-64.log"

rm -f "$box/out/prediction-room@path-64-pixels.json"
mkfifo "$box/out/prediction-room@path-64-pixels.json"
expect_refused "a prediction is a FIFO" \
  "'$box/out/prediction-room@path-64-pixels.json' is a FIFO, not a regular file" \
  root/scripts/rtw-turns.sh "$box/out" 64 "$box/scenes/room.gltf"
rm "$box/out/prediction-room@path-64-pixels.json"

echo "not a folder" >"$box/file"
expect_refused "the output folder is a file" "OUTDIR '$box/file' is not a folder" \
  root/scripts/rtw-turns.sh "$box/file" 64 "$box/scenes/room.gltf@0"

if timeout 20 "$box/root/scripts/rtw-turns.sh" "$box/out" 64 "$box/scenes/room.gltf@0" \
  2>/dev/null && grep -q "stub bench output" "$box/out/turns-room@0-64.log"; then
  ok "a good run wrote its log"
else
  failed "a good run: no log turns-room@0-64.log"
fi
expect_no_temporary "a good run" "$box/out"
finish
