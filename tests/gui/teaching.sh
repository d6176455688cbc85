#!/usr/bin/env bash
# The teaching controls (shadowlab-gui-tests --test teaching=DIR, see tests/gui/src/GuiTests.cpp)
# on `diagonal` with DA-RTW: ] steps through the passes of one frame as da-rtw and the
# renderer declare them (TechniqueInfo::passes; the same order as the timed passes), each
# raising and marking the panel that shows its output, and past the last pass renders exactly one more frame; Esc resumes;
# O cycles every overlay the `view.overlay` declaration lists; F7 splits the view with both
# errors measured; V shows the outside view, a drag there turns the third camera only;
# every lesson in scenes/lessons applies its scene and technique. The
# window at each step is saved to DIR for a look.
# usage: teaching.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/teaching
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test teaching" 120 "$out/teaching" \
  "$tests" --scene diagonal --technique da-rtw --test "teaching=$out"
python3 "$here/pngstats.py" --min-colors 64 --min-stddev 8 "$out"/pass-*.png "$out/split.png"
echo "PASS"
