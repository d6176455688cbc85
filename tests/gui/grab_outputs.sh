#!/usr/bin/env bash
# The GUI's writers keep the run's inputs (the output policy of algo/OutputFile.h): --grab
# into the folder of a scene whose buffer is named viewport.png (tests/fixtures/hostile/
# grab-into-scene), into a folder holding the session it opened as published.json, one with a
# FIFO named published.json, and one whose viewport.png is a symbolic link to the scene: each
# is refused before any frame in one line (exit 2), nothing replaced, no hang. A grab into a
# folder with an old viewport.png replaces it whole (no temporary file left). Then the
# output-policy GUI test: Save session and Export figure refuse the scene's files, a link to
# one, and a FIFO.
# usage: grab_outputs.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1 tests=$4
out=$3/grab_outputs
here=$(cd "$(dirname "$0")" && pwd)
fixture=$here/../fixtures/hostile/grab-into-scene
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb
fail=0

# refused NAME WANT-REGEX ARGS...: exit 2 within 60 s, one stderr line matching WANT.
refused() {
  local name=$1 want=$2
  shift 2
  local rc=0
  timeout 60 "$app" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr" || rc=$?
  local lines
  lines=$(grep -c . "$out/$name.stderr" || true)
  if [[ $rc -ne 2 || $lines -ne 1 ]] || ! grep -qE -- "$want" "$out/$name.stderr"; then
    echo "FAIL: $name: exit $rc (expected 2), $lines stderr lines, expected one matching '$want':"
    cat "$out/$name.stderr"
    fail=1
  else
    echo "ok   $name: $(cat "$out/$name.stderr")"
  fi
}
# unchanged NAME FILE COPY: FILE still has COPY's bytes.
unchanged() {
  cmp -s "$2" "$3" || { echo "FAIL: $1: $2 was changed"; fail=1; }
}

# 1. Into the scene's own folder: its buffer viewport.png would be replaced.
cp -r "$fixture" "$out/scene"
cp "$fixture/viewport.png" "$out/buffer.orig"
refused scene-folder "^shadowlab: --grab: viewport\.png: '.*/viewport\.png' is the same file as the scene's file .*viewport\.png \(the input would be overwritten\)$" \
  --scene "$out/scene/scene.gltf" --technique uniform --grab "$out/scene" --grab-after 2
unchanged scene-folder "$out/scene/viewport.png" "$out/buffer.orig"
[[ ! -e "$out/scene/window.png" ]] || { echo "FAIL: scene-folder: window.png written"; fail=1; }

# 2. The session it opened, named published.json in the grab's folder.
mkdir -p "$out/session"
python3 - "$out/scene/scene.gltf" "$out/session/published.json" <<'PY'
import json, sys
json.dump({"title": "s", "scene": sys.argv[1], "technique": "uniform"}, open(sys.argv[2], "w"))
PY
cp "$out/session/published.json" "$out/session.orig"
refused session "^shadowlab: --grab: published\.json: .* is the same file as the lesson or session .*published\.json \(the input would be overwritten\)$" \
  --open-session "$out/session/published.json" --grab "$out/session" --grab-after 2
unchanged session "$out/session/published.json" "$out/session.orig"

# 3. A FIFO named published.json: refused at once (writing into it hung the grab).
mkdir -p "$out/fifo" && mkfifo "$out/fifo/published.json"
refused fifo "^shadowlab: --grab: published\.json: .* is a FIFO, not a regular file: refused" \
  --scene default --technique uniform --grab "$out/fifo" --grab-after 2

# 4. viewport.png a symbolic link to the scene's glTF: resolved first, refused.
mkdir -p "$out/link" && ln -s "$out/scene/scene.gltf" "$out/link/viewport.png"
cp "$out/scene/scene.gltf" "$out/scene.orig"
refused link "is the same file as the scene's file .*scene\.gltf" \
  --scene "$out/scene/scene.gltf" --technique uniform --grab "$out/link" --grab-after 2
unchanged link "$out/scene/scene.gltf" "$out/scene.orig"

# 5. A grab that may write: an old viewport.png replaced whole, no temporary file left.
mkdir -p "$out/good" && echo old >"$out/good/viewport.png"
rc=0
timeout 300 "$app" --scene default --technique uniform --grab "$out/good" --grab-after 2 \
  >"$out/good.stdout" 2>"$out/good.stderr" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: good: exit $rc"; cat "$out/good.stderr"; fail=1
else
  python3 "$here/pngstats.py" --min-colors 8 "$out/good/viewport.png" || fail=1
  left=$(find "$out/good" -name '.*tmp*')
  [[ -z $left ]] || { echo "FAIL: good: temporary files left: $left"; fail=1; }
  echo "ok   good: viewport.png replaced, no temporary file"
fi

# 6. The window's other writers (Save session, Export figure, image exports).
ln -s "$out/scene/scene.gltf" "$out/scene/link.json"
mkfifo "$out/scene/fifo.png"
run_gui_test output-policy 300 "$out/output-policy" "$tests" --scene "$out/scene/scene.gltf" \
  --technique uniform --test "output-policy=$out/scene" || fail=1
unchanged output-policy "$out/scene/viewport.png" "$out/buffer.orig"
unchanged output-policy "$out/scene/scene.gltf" "$out/scene.orig"

[[ $fail -eq 0 ]] && echo "PASS"
exit $fail
