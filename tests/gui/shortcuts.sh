#!/usr/bin/env bash
# Keys from anywhere in the window (shadowlab-gui-tests --test shortcuts, see
# tests/gui/src/GuiTestsShortcuts.cpp): with a Parameters slider or a dock's tree focused,
# V, F6, Space, O and W held act on the view, also from every kind of widget and a floating
# dock; typed into a spin box, V, Space and W stay its own; a drag orbits 180° per view height,
# a wheel notch moves 15 % of the distance to the target; F1 lists every command.
# usage: shortcuts.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
tests=$4
out=$3/shortcuts
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test shortcuts" 120 "$out/shortcuts" \
  "$tests" --scene default --technique uniform --test shortcuts
echo "PASS"
