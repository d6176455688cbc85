#!/usr/bin/env bash
# Presenter mode on a 1920x1080 and a 1280x720 screen (issue 15): started with --presenter
# (what the lesson grabs use) on the first, turned on through its action (F11) on the second;
# the self-test checks the window fits, body text >= 22 px x min(w/1920, h/1080), one big
# panel image >= 35 % of the screen's height, the changed overlay's pixels = the renderer's
# count, the pointer ring, the zoom inset, the ticks. PNGs in <out>/presenter.
# usage: presenter.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/presenter
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"

for screen in 1920x1080 1280x720; do
  XVFB_SCREEN="${screen}x24" start_xvfb
  flag=()
  [[ $screen == 1920x1080 ]] && flag=(--presenter)
  rc=0
  timeout 240 "$app" --scene corridor --technique uniform --set resolution=1024 "${flag[@]}" \
    --self-test "presenter=$out" >"$out/$screen.stdout" 2>"$out/$screen.stderr" || rc=$?
  stop_xvfb
  echo "[$screen ${flag[*]}]"
  cat "$out/$screen.stdout"
  if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/$screen.stdout"; then
    echo "FAIL: self-test presenter at $screen exited with $rc; stderr:"
    cat "$out/$screen.stderr"
    exit 1
  fi
  [[ -s "$out/presenter-$screen.png" ]] || { echo "FAIL: no presenter-$screen.png"; exit 1; }
done
echo "PASS"
