#!/usr/bin/env bash
# DA-RTW's turn prediction in the Covariance panel at 1280x800, the projector's smaller size
# (shadowlab-gui-tests --test turn-prediction, see tests/gui/src/GuiTestsPanels.cpp): on
# band-diagonal the panel plots the predicted score of every turn with now, was and PCA's axis
# marked, R stands at the curve's lowest point (±45°) and the state says why; "Measure the
# error at these turns" measures the 13 fixed turns and the current one on the render thread
# while the window keeps answering, and the measured error agrees with the prediction on the
# best turn. The panel's PNG is kept in the output folder.
# usage: turn_prediction.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
tests=$4
out=$3/turn_prediction
here=$(cd "$(dirname "$0")" && pwd)
export XVFB_SCREEN=1280x800x24
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test turn-prediction" 400 "$out/turn_prediction" \
  "$tests" --scene band-diagonal --technique da-rtw --test "turn-prediction=$out"
python3 "$here/pngstats.py" --min-colors 200 --min-stddev 10 "$out/covariance-turn-prediction.png"
echo "PASS"
