#!/usr/bin/env bash
# Courses (scenes/courses.json): `shadowlab --course 45` opens the course's first lesson, and
# the Lesson dock's Next opens each next lesson of the course in its order, the dock showing
# "Course 45 min: K of 7 · ~T min" (shadowlab-gui-tests --test course=DIR, see tests/gui/src/GuiTestsCourse.cpp;
# the dock at each lesson is saved to DIR). An unknown course and a course file naming a
# missing lesson each stop the program with one line naming what is wrong.
# usage: course.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/course
here=$(cd "$(dirname "$0")" && pwd)
scenes=$(cd "$here/../../scenes" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test course" 300 "$out/course" \
  "$tests" --course 45 --test "course=$out"
python3 "$here/pngstats.py" --min-colors 16 --min-stddev 4 "$out"/course-*.png

# expect_refusal <what> <expected stderr line> <command...>: exit 2 and exactly that one line.
expect_refusal() {
  local what=$1 want=$2 rc=0
  shift 2
  "$@" >"$out/refusal.stdout" 2>"$out/refusal.stderr" || rc=$?
  local got
  got=$(cat "$out/refusal.stderr")
  if [[ $rc -ne 2 || "$got" != "$want" ]]; then
    echo "FAIL: $what: exit $rc, stderr:"
    cat "$out/refusal.stderr"
    echo "expected exit 2 and: $want"
    exit 1
  fi
  echo "ok   $what: $got"
}

expect_refusal "an unknown course" "shadowlab: unknown course '30' (known: 90, 45)" \
  "$app" --course 30 --grab "$out/never"
expect_refusal "--course with --lesson" \
  "shadowlab: --course and --lesson (or --open-session): give one of them" \
  "$app" --course 45 --lesson 1 --grab "$out/never"

# A course file naming a lesson that is not there (the built-in lessons, a bad course file).
bad=$out/bad-scenes
mkdir -p "$bad"
ln -s "$scenes/lessons" "$bad/lessons"
cat >"$bad/courses.json" <<'JSON'
{"courses": [{"name": "45", "minutes": 45, "lessons": [
  {"lesson": "01-perspective-aliasing.json", "minutes": 5},
  {"lesson": "07-no-such-lesson.json", "minutes": 5}]}]}
JSON
expect_refusal "a course file naming a missing lesson" \
  "shadowlab: $bad/courses.json: courses[0].lessons[1].lesson: no lesson '07-no-such-lesson.json' in $bad/lessons" \
  env SHADOWLAB_SCENE_DIR="$bad" "$app" --course 45 --grab "$out/never"
[[ ! -e "$out/never" ]] || { echo "FAIL: a refused start wrote $out/never"; exit 1; }
echo "PASS"
