#!/usr/bin/env bash
# Each lesson's claim, in numbers (shadowlab --self-test lesson-claims=DIR, see
# ui/SelfTestsLessons.cpp): every lesson in scenes/lessons opened fresh, in order, its temporal
# state settled, only its listed panels shown and its telling panel large; the claims read
# from the lessons' own texts and measured: perspective aliasing (m in three bands, the error
# thin lines along the exact shadow's edges), projective aliasing (m on grazed faces against
# faces turned to the light), RTW against uniform at the same texels in the split view, the
# PCA's settled angle (twice), the vibration (changed pixels per frame, none once held).
# The window of each lesson is saved to DIR for a look.
# usage: lesson_claims.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/lesson_claims
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 600 "$app" --self-test "lesson-claims=$out" >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
cat "$out/stdout.txt"
if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/stdout.txt"; then
  echo "FAIL: self-test lesson-claims exited with $rc; stderr:"
  cat "$out/stderr.txt"
  exit 1
fi
python3 "$here/pngstats.py" --min-colors 64 --min-stddev 8 "$out"/[0-9]*.png
echo "PASS"
