#!/usr/bin/env bash
# Opening a broken session from the GUI (issue 14 item 6, sessions of issue 15) — File > Open
# session… with Qt's file dialog, and dropping the .json on the window (a QDropEvent with its
# URL), driven by shadowlab-gui-tests --test bad-session=FILE,FILE,… (tests/gui/src/GuiTests.cpp) — shows an
# error dialog and a status message naming the file, and the current scene, technique,
# parameters and split view stay (the window keeps rendering). Every broken session fixture of
# tests/fixtures/hostile (the CLI's messages for them: expected.tsv), a session naming a broken
# scene, a JSON nested 1,000 deep, a syntax error, plus a generated FIFO and a file over the
# 16 MiB JSON limit.
# usage: open_bad_session.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$(realpath "$1")
tests=$(realpath "$4")
out=$(realpath -m "$3")/open_bad_session
here=$(cd "$(dirname "$0")" && pwd)
hostile=$(cd "$here/../fixtures/hostile" && pwd)
source "$here/xvfb.bash"
source "$here/bad_files.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

files=()
for f in "$hostile"/session-*.json; do
  [[ $(basename "$f") == session-valid.json ]] && continue
  files+=("$f")
done
[[ ${#files[@]} -ge 5 ]] || { echo "FAIL: only ${#files[@]} session fixtures in $hostile"; exit 1; }
for f in preset-broken-scene.json deep-1000.json preset-syntax-error.json; do
  [[ -f "$hostile/$f" ]] || { echo "FAIL: fixture $hostile/$f is missing"; exit 1; }
  files+=("$hostile/$f")
done
mkfifo "$out/pipe.json"
truncate -s 17M "$out/big.json"
files+=("$out/pipe.json" "$out/big.json")

list=$(IFS=,; echo "${files[*]}")
rc=0
# From the fixtures' folder: preset-broken-scene.json names its scene relative (dag-24.gltf).
(cd "$hostile" && timeout 300 "$tests" --scene default --technique uniform \
  --test "bad-session=$list") >"$out/gui-test.stdout" 2>"$out/gui-test.stderr" || rc=$?
check_bad_files bad-session "File > Open session" "$out" "$rc" "${files[@]}"
rm -f "$out/big.json" "$out/pipe.json"
echo "PASS"
