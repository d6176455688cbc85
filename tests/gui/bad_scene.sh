#!/usr/bin/env bash
# A scene file that does not exist: --grab exits non-zero with a message naming the file,
# and writes no images. A lesson whose scene does not exist is a problem of the grab too: it
# exits 1 with a "grab failed:" line naming the file (it exited 0, grabbing a blank view).
# usage: bad_scene.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1 data=$2
out=$3/bad_scene
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

missing=/nonexistent.gltf
rc=0
timeout 120 "$app" --scene "$missing" --grab "$out/grab" >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
cat "$out/stderr.txt"
[[ $rc -ne 0 ]] || { echo "FAIL: exit code 0 for a missing scene"; exit 1; }
[[ $rc -ne 124 ]] || { echo "FAIL: timed out"; exit 1; }
grep -qF "$missing" "$out/stderr.txt" || { echo "FAIL: stderr does not name $missing"; exit 1; }
[[ ! -e "$out/grab/window.png" ]] || { echo "FAIL: window.png written anyway"; exit 1; }

rc=0
timeout 300 "$app" --lesson "$data/presets/grab-missing-scene.json" --grab "$out/lesson" \
  --grab-after 2 >"$out/lesson.stdout" 2>"$out/lesson.stderr" || rc=$?
cat "$out/lesson.stderr"
[[ $rc -eq 1 ]] || { echo "FAIL: a lesson whose scene is missing: exit $rc, expected 1"; exit 1; }
grep -qE "^shadowlab: grab failed: .*no-such-folder/no-such-scene\.gltf" "$out/lesson.stderr" ||
  { echo "FAIL: no 'grab failed' line naming the lesson's scene"; exit 1; }
echo "PASS"
