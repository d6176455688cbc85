#!/usr/bin/env bash
# The split view after the window is dragged to its smallest and back (issue 14): the view
# pinned, measured, shrunk to 3x3, 2x2, 1x1 and 0x0, restored, measured again. Both halves
# must measure the same error as before (a view below 16 px is not rendered, so DA-RTW's
# rotation is not taken from a degenerate 2-pixel frame), and no size reports a problem.
# usage: split_resize.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/split_resize
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

for pair in "uniform da-rtw"; do
  read -r left right <<<"$pair"
  echo "[$left | $right]"
  run_gui_test "GUI test split-resize ($left | $right)" 240 "$out/$left-$right" \
    "$tests" --scene default --technique "$left" --test "split-resize=$right"
  [[ $(grep -c "^ok   .x., right half" "$out/$left-$right.stdout") -eq 4 ]] ||
    { echo "FAIL: not every size was checked"; exit 1; }
done
echo "PASS"
