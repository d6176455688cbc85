#!/usr/bin/env bash
# Sessions (issue 15 item 4): a non-default state (scene, technique, parameters, overlay,
# camera, light, a split technique with its own parameter, a hidden dock) saved through
# File > Save session; the app restarted with --open-session FILE must show the same frame: the
# same metrics (error % of both halves, techniques, every parameter value, camera, light,
# visible docks), printed by both runs and compared here. The save run also checks Recent
# sessions (at most 8, a deleted file dropped with a message) and that malformed sessions are
# refused with the file named and the state kept.
# usage: session_roundtrip.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/session_roundtrip
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb
session=$out/my-session.json

run() {  # name, arguments...
  local name=$1
  shift
  echo "[$name]"
  run_gui_test "$name" 300 "$out/$name" "$tests" "$@"
}

run save --scene default --technique uniform --test "session-save=$session"
[[ -s $session ]] || { echo "FAIL: no session file written"; exit 1; }
run open --open-session "$session" --test session-check
# --lesson FILE opens the same file: a session is a lesson.
run lesson --lesson "$session" --test session-check

grep '^metric ' "$out/save.stdout" >"$out/save.metrics"
[[ $(wc -l <"$out/save.metrics") -gt 20 ]] || { echo "FAIL: too few metrics"; exit 1; }
for m in 'technique=cascades' 'split.technique=uniform' 'param.partitions=3' \
  'param.view.overlay=aliasing' 'split.param.resolution=512' 'scene=corridor'; do
  grep -qx "metric $m" "$out/save.metrics" || { echo "FAIL: the saved state lacks $m"; exit 1; }
done
grep -q '^metric error_pct=[0-9]' "$out/save.metrics" || { echo "FAIL: no error measured"; exit 1; }
for name in open lesson; do
  grep '^metric ' "$out/$name.stdout" >"$out/$name.metrics"
  if ! diff -u "$out/save.metrics" "$out/$name.metrics"; then
    echo "FAIL: the restarted app ($name) does not show the saved state"
    exit 1
  fi
done
echo "the same $(wc -l <"$out/save.metrics") metrics after the restart"
echo "PASS"
