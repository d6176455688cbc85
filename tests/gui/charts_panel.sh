#!/usr/bin/env bash
# The Charts panel (shadowlab-gui-tests --test charts=DIR, see tests/gui/src/GuiTests.cpp): a tiny
# sweep (uniform at 2 resolutions and rtw-backward at 256, x 2 frames) runs to completion
# while the view goes on drawing (a view frame comes before the sweep ends),
# the chart is saved as panel-charts.png; the x combo box switches axis and Pareto front to
# memory (panel-charts-bytes.png) and back without a new sweep; a click on a point switches
# the view to that configuration (technique, resolution, technique combo); a sweep of a
# sky-only view (dueling, camera looking up) gives error n/a (NaN, never 0), draws no point and
# says so in the panel's status line.
# usage: charts_panel.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/charts_panel
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test charts" 90 "$out/charts" \
  "$tests" --scene plane-box --technique rtw-backward --test "charts=$out"
[[ -s "$out/panel-charts.png" ]] || { echo "FAIL: no panel-charts.png"; exit 1; }
[[ -s "$out/panel-charts-bytes.png" ]] || { echo "FAIL: no panel-charts-bytes.png"; exit 1; }
echo "PASS"
