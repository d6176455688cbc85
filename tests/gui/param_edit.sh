#!/usr/bin/env bash
# Live parameter edits through the generated Parameters panel (shadowlab-gui-tests --test
# params, see tests/gui/src/GuiTests.cpp): typing a value into an editor changes the
# renderer's value and the next frame (image brightness for shading.ambient, the shadow
# map's size for resolution); an out-of-range entry is refused with the declaration's
# range in the status bar and nothing changes.
# usage: param_edit.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/param_edit
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

for technique in uniform rtw-backward; do
  echo "[$technique]"
  run_gui_test "GUI test params with $technique" 120 "$out/$technique" \
    "$tests" --scene plane-box --technique "$technique" --test params
  grep -q "^ok   typing 5 (out of range)" "$out/$technique.stdout" ||
    { echo "FAIL: the out-of-range check did not run"; exit 1; }
done
echo "PASS"
