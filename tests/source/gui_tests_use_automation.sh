#!/usr/bin/env bash
# The GUI tests (tests/gui/src) drive the window through ui/Automation.h, as a script would:
# no call of a MainWindow member (its accessors `viewport()`, `lessons()`, `statusBar()`, …)
# on the window (`w_.`, `window().`). The calls not yet ported are listed below by name; a
# name leaves the list once Automation offers what the tests read through it, and no other
# name may come back.
# usage: gui_tests_use_automation.sh <repository root>
set -euo pipefail
root=$1
# Not yet ported to Automation: each still called by some test.
pending=(viewport chartsPanel lessons presenter docks sessions grab teaching lessonPanel
  paramPanel paramDock width height timingDock chartsDock screen passes isActiveWindow
  frameGeometry dockWidgetArea windowTitle techniqueCombo sceneCombo minimumSizeHint menuBar
  lessonDock activateWindow timingPanel tabifiedDockWidgets syncLightControls splitSide report
  rect raise openAction)
allowed=$(printf '%s|' "${pending[@]}")
allowed=${allowed%|}
calls=$(grep -noE '\b(w_|window\(\))\.[A-Za-z_]+\(' "$root"/tests/gui/src/*.cpp "$root"/tests/gui/src/*.h |
  grep -vE ":(w_|window\(\))\.($allowed)\($" || true)
if [[ -n $calls ]]; then
  echo "FAIL: GUI tests call the window instead of ui/Automation.h:"
  echo "$calls" | sed "s|^$root/||"
  exit 1
fi
left=$(grep -ohE '\b(w_|window\(\))\.[A-Za-z_]+\(' "$root"/tests/gui/src/*.cpp "$root"/tests/gui/src/*.h | wc -l)
echo "GUI tests: no window call outside the ${#pending[@]} names not yet ported ($left calls left)"
