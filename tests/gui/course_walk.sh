#!/usr/bin/env bash
# A lecturer walks a course: `--course 45` and `--course 90`, presenter mode, Next from the
# first lesson to the last, on a 1920x1080 and a 1280x800 screen (shadowlab-gui-tests --test
# course-claims=DIR, see tests/gui/src/GuiTestsCourse.cpp). After each Next the lesson must
# pass the checks it passes when opened alone (lesson_claims.sh): settled, its layout, the
# window on its screen, its live numbers filled, its claims measured. By default the
# 45-minute course at 1920x1080 and the 90-minute course (every lesson) at 1280x800;
# COURSE_WALK_ALL=1 walks both courses on both screens.
# usage: course_walk.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
tests=$4
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
walks=("45 1920x1080" "90 1280x800")
[[ "${COURSE_WALK_ALL:-0}" == 1 ]] && walks=("45 1920x1080" "90 1920x1080" "45 1280x800" "90 1280x800")
fail=0
for walk in "${walks[@]}"; do
  read -r minutes screen <<<"$walk"
  out=$3/course_walk-$minutes-$screen
  rm -rf "$out" && mkdir -p "$out"
  export XVFB_SCREEN=${screen}x24
  start_xvfb
  rc=0
  timeout 900 "$tests" --course "$minutes" --presenter --test "course-claims=$out" \
    >"$out/log.out" 2>"$out/log.err" || rc=$?
  stop_xvfb
  cat "$out/log.out"
  if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/log.out"; then
    echo "FAIL: the $minutes-minute course at $screen exited with $rc; stderr:"
    tail -n 20 "$out/log.err"
    fail=1
  fi
done
[[ $fail -eq 0 ]] && echo "PASS"
exit $fail
