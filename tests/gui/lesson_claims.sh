#!/usr/bin/env bash
# Each lesson's claim, in numbers (shadowlab --lesson NAME --test lesson-claims=DIR, see
# tests/gui/src/GuiTestsLessons.cpp): every lesson in scenes/lessons started fresh, as
# scripts/grab_lessons.sh grabs it (the same screen and presenter mode, so the same window and
# view): its temporal state settled, only its listed panels shown and its telling panel large;
# the claims read from the lesson's own text and measured: perspective aliasing (m in three
# bands, the error thin lines along the exact shadow's edges), projective aliasing (the floor's
# m at a low and a high sun), RTW against uniform at the same texels in the split view, the
# PCA's settled angle (two fresh starts, the same angle), the vibration (changed pixels per
# frame, none once held), forward against backward analysis (texels given importance, error),
# LiSPSM's η (error and m from η = -1 to 0 and 1), face partitioning against lispsm and uniform
# at the same texels, the cascades' split schemes (each map's m), cube against dual paraboloid
# (memory, error, tessellation), FVSM against a small brute-force budget and ASM against RMSM
# (both errors, the Pages panel's counts, uniform and rtw-backward staged). The window of each
# lesson is saved to DIR for a look. Every lesson's window fits its screen, every live number
# of its text is filled and no label on screen cuts its text. LESSON_SCREEN (default
# 1920x1080) is the screen's size: lesson_claims_1280x800.sh runs the same at 1280x800.
# usage: lesson_claims.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
screen=${LESSON_SCREEN:-1920x1080}
out=$3/lesson_claims-$screen
here=$(cd "$(dirname "$0")" && pwd)
export XVFB_SCREEN=${screen}x24
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

fail=0
declare -A angle
for json in "$here"/../../scenes/lessons/*.json; do
  name=$(basename "$json" .json)
  runs=1
  [[ $name == *diagonal-pca ]] && runs=2  # from a fresh start, every run: the same angle
  for run in $(seq $runs); do
    log=$out/$name-$run
    rc=0
    timeout 300 "$tests" --lesson "$name" --presenter --test "lesson-claims=$out" \
      >"$log.out" 2>"$log.err" || rc=$?
    cat "$log.out"
    if [[ $rc -ne 0 ]] || ! grep -qx PASS "$log.out"; then
      echo "FAIL: $name (run $run) exited with $rc; stderr:"
      tail -n 20 "$log.err"
      fail=1
    fi
    a=$(sed -n 's/^metric rotation_deg=//p' "$log.out")
    [[ -n "$a" ]] && angle[$run]=$a
  done
done
if [[ -n "${angle[1]:-}" && "${angle[1]}" != "${angle[2]:-}" ]]; then
  echo "FAIL: the PCA lesson settled at ${angle[1]}° and then at ${angle[2]:-?}°"
  fail=1
fi
python3 "$here/pngstats.py" --min-colors 64 --min-stddev 8 "$out"/[0-9]*.png || fail=1
[[ $fail -eq 0 ]] && echo "PASS"
exit $fail
