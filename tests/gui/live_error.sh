#!/usr/bin/env bash
# Continuous rendering keeps the error live (issue 15 item 6): F6 on, the readout shows a
# number and the reference's age within a time limit (traced on a worker thread, equal to the
# synchronous error of the same view); a camera move makes it stale and greyed (read in the
# first frame after it), then fresh; a scene change shows nothing of the old scene; the split
# view's right half has its own live error
# (its age in its caption, equal to its synchronous error, stale after a move then fresh); the
# window closes right after a move (a trace possibly running), exit 0.
# usage: live_error.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/live_error
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test live-error" 300 "$out/live" \
  "$tests" --scene default --technique uniform --test "live-error=$out"
grep -q '^measure live_error_first_ms=' "$out/live.stdout" || { echo "FAIL: no measurement"; exit 1; }
echo "PASS"
