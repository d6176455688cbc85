#!/usr/bin/env bash
# Grabs every lesson's window as a class sees it, on two screens: opens each
# scenes/lessons/*.json with `shadowlab --lesson NAME --presenter` on a private Xvfb of each
# size in SIZES (default "1920x1080 1280x800"), lets the lesson settle (a grab waits for the
# lesson's temporal state) and saves the window as OUTDIR/<lesson>.png (the first size) and
# OUTDIR/<size>/<lesson>.png (the others); a lesson told in cases also as <lesson>-case<K>.png
# for its other cases. A window larger than its screen fails the run (exit 1, naming the
# lesson, the window and the screen). docs/lecturer/lessons.md shows the grabs in
# docs/images/lessons/.
# LESSONS (default "*") chooses lessons by name pattern, e.g. LESSONS="06-* 07-*".
# COURSE=90 (or 45) takes the grabs as a lecturer walks that course instead: one run of
# `shadowlab-gui-tests --course 90 --presenter --test course-grabs=DIR` per size (GUI_TESTS,
# default build/tests/shadowlab-gui-tests), Next from the first lesson to the last, each
# lesson grabbed once it has settled and its panels are filled, a lesson told in cases also
# in its other cases; lessons outside the course are not grabbed.
# The PNGs follow the output policy (scripts/lib/output.sh): one that is a lesson file, a folder,
# a FIFO or a device is refused before the first grab (exit 2); each is replaced only when its
# grab succeeded, never half-copied.
# usage: [COURSE=90] scripts/grab_lessons.sh OUTDIR [path/to/shadowlab] [frames before the grab (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/scripts/lib/output.sh"
out=${1:?usage: scripts/grab_lessons.sh OUTDIR [shadowlab] [frames]}
app=${2:-$root/build/app/shadowlab}
frames=${3:-3}
sizes=(${SIZES:-1920x1080 1280x800})
[[ -x "$app" ]] || { echo "grab_lessons: no executable $app (build first)" >&2; exit 1; }
course=${COURSE:-}
tests=${GUI_TESTS:-$root/build/tests/shadowlab-gui-tests}
walked=()  # the course's lessons (file names without .json), in its order
if [[ -n $course ]]; then
  [[ -x "$tests" ]] || { echo "grab_lessons: no executable $tests (build first)" >&2; exit 1; }
  mapfile -t walked < <(python3 -c '
import json, sys
for c in json.load(open(sys.argv[1]))["courses"]:
    if c["name"] == sys.argv[2]:
        for l in c["lessons"]: print(l["lesson"].removesuffix(".json"))
        sys.exit(0)
sys.exit("grab_lessons: no course %s in %s" % (sys.argv[2], sys.argv[1]))' "$root/scenes/courses.json" "$course")
fi
output_folder OUTDIR "$out"
out=$(cd "$out" && pwd)
# The shots: every chosen lesson, and its other cases as <lesson>-case<K>.
shots=()
for json in "$root"/scenes/lessons/*.json; do
  name=$(basename "$json" .json)
  chosen=0
  read -ra patterns <<<"${LESSONS:-*}"
  for pattern in "${patterns[@]}"; do
    # shellcheck disable=SC2053  # the pattern is a glob on purpose
    [[ $name == $pattern ]] && chosen=1
  done
  if [[ -n $course ]]; then
    in_course=0
    for w in "${walked[@]}"; do [[ $w == "$name" ]] && in_course=1; done
    [[ $in_course -eq 1 ]] || chosen=0
  fi
  [[ $chosen -eq 1 ]] || continue
  output_input "the lesson" "$json"
  cases=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1])).get("cases", [])))' "$json")
  for k in $(seq 1 $((cases > 1 ? cases : 1))); do
    shot=$name
    [[ $k -gt 1 ]] && shot=$name-case$k
    shots+=("$name $k $shot")
  done
done
output_input "the program" "$app"
[[ -n $course ]] && output_input "the program" "$tests"
# Every PNG of every size, checked before the first grab.
first=1
for size in "${sizes[@]}"; do
  dest=$out
  [[ $first -eq 0 ]] && dest=$out/$size
  for entry in "${shots[@]}"; do output_check "the grab" "$dest/${entry##* }.png"; done
  first=0
done
source "$root/tests/gui/xvfb.bash"
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-grab-lessons.XXXXXX")
trap 'rm -rf "$work"; stop_xvfb; output_cleanup' EXIT
# The size of a PNG (its IHDR), without an image library.
png_size() {
  python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); print("%dx%d" % struct.unpack(">II", d[16:24]))' "$1"
}
fail=0
first=1
for size in "${sizes[@]}"; do
  export XVFB_SCREEN=${size}x24
  start_xvfb
  dest=$out
  [[ $first -eq 0 ]] && dest=$out/$size
  if [[ -n $course ]]; then  # one walk of the course: every lesson's grab in $work/walk-$size
    walk=$work/walk-$size
    if ! timeout 1800 "$tests" --course "$course" --presenter --test "course-grabs=$walk" \
      >"$walk.log" 2>&1 || ! grep -qx PASS "$walk.log"; then
      echo "grab_lessons: the walk of the $course-minute course at $size failed:" >&2
      grep -v '^ok ' "$walk.log" | tail -n 20 >&2
      fail=1
    fi
  fi
  for entry in "${shots[@]}"; do
    read -r name k shot <<<"$entry"
    rm -rf "${work:?}/$shot"
    grabbed=$work/$shot/window.png
    if [[ -n $course ]]; then
      grabbed=$walk/$shot.png
      [[ -f $grabbed ]] || echo "grab_lessons: the walk grabbed no $shot" >"$work/$shot.log"
    fi
    if { [[ -n $course ]] ||
      timeout 300 "$app" --lesson "$name" --lesson-case "$k" --presenter --grab "$work/$shot" \
        --grab-after "$frames" >"$work/$shot.log" 2>&1; } && [[ -f "$grabbed" ]]; then
      got=$(png_size "$grabbed")
      if (( ${got%x*} > ${size%x*} || ${got#*x} > ${size#*x} )); then
        echo "grab_lessons: $shot: the window ($got) is larger than the ${size} screen" >&2
        fail=1
      fi
      output_write "$dest/$shot.png" cat "$grabbed"
      echo "$dest/$shot.png ($got)"
    else
      echo "grab_lessons: $shot at $size failed:" >&2
      tail -n 20 "$work/$shot.log" >&2
      fail=1
    fi
  done
  stop_xvfb
  first=0
done
rm -rf "$work"
exit $fail
