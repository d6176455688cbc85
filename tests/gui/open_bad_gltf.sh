#!/usr/bin/env bash
# Opening a broken glTF from the GUI (File > Open glTF… with Qt's file dialog, driven by
# shadowlab --self-test bad-gltf=FILE, see ui/MainWindowSelfTest.cpp) shows an error
# dialog naming the file, and the previous scene stays loaded and keeps rendering.
# usage: open_bad_gltf.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
data=$2
out=$3/open_bad_gltf
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

for broken in malformed.gltf truncated.glb; do
  rc=0
  timeout 120 "$app" --scene plane-box --technique uniform --self-test "bad-gltf=$data/$broken" \
    >"$out/$broken.stdout" 2>"$out/$broken.stderr" || rc=$?
  echo "[$broken]"
  cat "$out/$broken.stdout"
  if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/$broken.stdout"; then
    echo "FAIL: self-test bad-gltf with $broken exited with $rc; stderr:"
    cat "$out/$broken.stderr"
    exit 1
  fi
  grep -qF "$broken" "$out/$broken.stderr" || { echo "FAIL: stderr does not name $broken"; exit 1; }
done
echo "PASS"
