#!/usr/bin/env bash
# Presets with messages that name things (issue 14): every bad preset in tests/data/presets/
# exits 2 with one line naming the file, the JSON path and what was expected (no library
# exception text); the lessons all load.
set -uo pipefail
cli=$1 data=$2 out=$3/preset-input
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
cd "$data/presets" || exit 1
fail=0

# expect_error FILE EXPECTED_LINE: exit 2 and stderr's last line exactly EXPECTED_LINE
# (a trailing '*' matches any rest).
expect_error() {
  local file=$1 want=$2 err rc line ok=1
  err=$(timeout 60 "$cli" render --preset "$file" --size 64x36 --out "$out/$file.png" 2>&1 >/dev/null)
  rc=$?
  line=$(printf '%s\n' "$err" | tail -n 1)
  if [[ "$want" == *'*' ]]; then
    [ "${line:0:$((${#want} - 1))}" == "${want%'*'}" ] || ok=0
  else
    [ "$line" == "$want" ] || ok=0
  fi
  if [ $rc -ne 2 ] || [ $ok -eq 0 ] || [[ "$err" == *json.exception* ]]; then
    printf 'FAIL: %s exited %s (expected 2) saying:\n  %s\nexpected:\n  %s\n' "$file" "$rc" "$line" "$want"
    fail=1
  fi
  if [ -e "$out/$file.png" ]; then echo "FAIL: $file: rendered anyway"; fail=1; fi
}

p="shadowlab-cli: --preset"
expect_error param-string.json \
  "$p: param-string.json: params.resolution: parameter 'resolution' takes 64..16384, got 'abc'"
expect_error unknown-param.json \
  "$p: unknown-param.json: params.resolutoin: technique 'uniform' has no parameter 'resolutoin'"
expect_error unknown-technique.json \
  "$p: unknown-technique.json: technique: unknown technique 'unifrom' (known: *"
expect_error camera-string.json \
  "$p: camera-string.json: camera.position[2]: expected a number, got \"x\""
expect_error camera-array.json \
  "$p: camera-array.json: camera: expected an object {...}, got [1,2,3]"
expect_error light-string.json \
  "$p: light-string.json: light.azimuthDeg: expected a number, got \"south\""
expect_error scene-number.json "$p: scene-number.json: scene: expected a string, got 7"
expect_error unknown-key.json \
  "$p: unknown-key.json: tecnique: unknown key 'tecnique' (known: *"
expect_error syntax-error.json \
  "$p: syntax-error.json: not valid JSON: parse error at line 1, column 33: *"

# Every lesson is a valid preset.
for f in "$here"/../../scenes/lessons/*.json; do
  if ! err=$(timeout 120 "$cli" render --preset "$f" --size 64x36 --out "$out/lesson.png" 2>&1 >/dev/null); then
    echo "FAIL: lesson $f: $err"; fail=1
  fi
done

[ $fail -eq 0 ] && echo "ok: every bad preset is refused naming its file and JSON path"
exit $fail
