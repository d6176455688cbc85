#!/usr/bin/env bash
# Grabs every lesson's window: opens each scenes/lessons/*.json with `shadowlab --lesson NAME`
# on a private 1920x1080 Xvfb (with --presenter when `shadowlab --help` lists it), lets the
# lesson settle (a grab waits for the lesson's temporal state) and saves the window as
# OUTDIR/<lesson>.png; a lesson told in cases also as OUTDIR/<lesson>-case<K>.png for its
# other cases. docs/lecturer/lessons.md shows the grabs in docs/images/lessons/.
# usage: scripts/grab_lessons.sh OUTDIR [path/to/shadowlab] [frames before the grab (3)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:?usage: scripts/grab_lessons.sh OUTDIR [shadowlab] [frames]}
app=${2:-$root/build/app/shadowlab}
frames=${3:-3}
[[ -x "$app" ]] || { echo "grab_lessons: no executable $app (build first)" >&2; exit 1; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
export XVFB_SCREEN=1920x1080x24
source "$root/tests/gui/xvfb.bash"
start_xvfb
extra=()
if "$app" --help 2>/dev/null | grep -q -- '--presenter'; then
  extra+=(--presenter)
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-grab-lessons.XXXXXX")
trap 'rm -rf "$work"; stop_xvfb' EXIT
fail=0
for json in "$root"/scenes/lessons/*.json; do
  name=$(basename "$json" .json)
  cases=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1])).get("cases", [])))' "$json")
  for k in $(seq 1 $((cases > 1 ? cases : 1))); do
    shot=$name
    [[ $k -gt 1 ]] && shot=$name-case$k
    rm -rf "${work:?}/$shot"
    if timeout 300 "$app" --lesson "$name" --lesson-case "$k" "${extra[@]}" --grab "$work/$shot" \
      --grab-after "$frames" >"$work/$shot.log" 2>&1 && [[ -f "$work/$shot/window.png" ]]; then
      cp "$work/$shot/window.png" "$out/$shot.png"
      echo "$out/$shot.png"
    else
      echo "grab_lessons: $shot failed:" >&2
      tail -n 20 "$work/$shot.log" >&2
      fail=1
    fi
  done
done
exit $fail
