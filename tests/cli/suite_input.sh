#!/usr/bin/env bash
# Suites that cannot pass by accident (issue 14): every bad suite in tests/data/suites/ is
# refused before any case runs (exit 2) with one line naming the file, the JSON path and
# what was expected, quoting at most ~200 bytes of the input and no library exception text;
# a case that ran no configuration fails (exit 1); a case that throws leaves the cases run
# before it in the --json file.
set -uo pipefail
cli=$1 data=$2 out=$3/suite-input
rm -rf "$out" && mkdir -p "$out"
cd "$data/suites" || exit 1
fail=0

# expect_error FILE RC EXPECTED_LINE: stderr's last line is exactly EXPECTED_LINE (a trailing
# '*' matches any rest: lists of known names), the exit code RC.
expect_error() {
  local file=$1 want_rc=$2 want=$3 err rc line
  err=$(timeout 60 "$cli" stability --suite "$file" --json "$out/$file.out" 2>&1 >/dev/null)
  rc=$?
  line=$(printf '%s\n' "$err" | tail -n 1)
  local ok=1
  if [[ "$want" == *'*' ]]; then
    [ "${line:0:$((${#want} - 1))}" == "${want%'*'}" ] || ok=0
  else
    [ "$line" == "$want" ] || ok=0
  fi
  if [ $rc -ne "$want_rc" ] || [ $ok -eq 0 ]; then
    printf 'FAIL: %s exited %s (expected %s) saying:\n  %s\nexpected:\n  %s\n' \
      "$file" "$rc" "$want_rc" "$line" "$want"
    fail=1
  fi
  if [[ "$err" == *json.exception* ]] || [ ${#line} -gt 400 ]; then
    echo "FAIL: $file: raw library text or a line over 400 bytes: ${line:0:400}"; fail=1
  fi
}

p="shadowlab-cli"
expect_error unknown-technique.json 2 \
  "$p: unknown-technique.json: cases[0].techniques[1].id: unknown technique 'unifrom' (known: *"
expect_error unknown-key.json 2 \
  "$p: unknown-key.json: cases[0].techniques[0].set.resolutoin: technique 'uniform' has no parameter 'resolutoin' (its own: *"
expect_error out-of-range.json 2 \
  "$p: out-of-range.json: cases[0].techniques[0].set.resolution: parameter 'resolution' = 99999 is out of range 64..16384"
expect_error nan-string.json 2 \
  "$p: nan-string.json: cases[1].techniques[1].set.resolution: parameter 'resolution': value is not a finite number (got \"nan\")"
expect_error expect-value-string.json 2 \
  "$p: expect-value-string.json: cases[0].expect[0].value: expected a number, got \"abc\""
expect_error frames-string.json 2 \
  "$p: frames-string.json: cases[0].frames: expected an integer in 1..1000000, got \"ten\""
expect_error technique-array.json 2 \
  "$p: technique-array.json: cases[0].techniques[0]: expected \"ID\" or {\"id\": ID, \"set\": {KEY: VALUE}, \"label\": L}, got [1,2]"
expect_error except-not-array.json 2 \
  "$p: except-not-array.json: cases[0].expect[0].except: expected an array [...], got \"uniform\""
expect_error unknown-case-key.json 2 \
  "$p: unknown-case-key.json: cases[0].frame: unknown key 'frame' (known: *"
expect_error syntax-error.json 2 \
  "$p: syntax-error.json: not valid JSON: parse error at line 1, column 52: *"
expect_error long-id.json 2 \
  "$p: long-id.json: cases[0].techniques[0].id: unknown technique '$(printf 'x%.0s' {1..60})... (20000 bytes)' (known: *"
expect_error only-optional.json 1 \
  "$p: FAILED case 'nothing-runs': the case runs at least one configuration (ran none: every technique was skipped)"
expect_error later-case-fails.json 2 \
  "$p: later-case-fails.json: cases[1] (case 'second'): camera: scene 'plane-box' has no camera 'no-such-bookmark' *"

# Refused at load time: nothing ran, so no --json was written.
for f in unknown-technique unknown-key out-of-range nan-string expect-value-string; do
  if [ -e "$out/$f.json.out" ]; then echo "FAIL: $f.json wrote results: it ran"; fail=1; fi
done
# The case before the one that threw is saved, and the file says it is incomplete.
python3 - "$out/later-case-fails.json.out" <<'PY' || fail=1
import json, sys
j = json.load(open(sys.argv[1]))
assert [c["name"] for c in j["cases"]] == ["first"], j["cases"]
assert j["complete"] is False and j["error"]["case"] == "second", j
assert j["passed"] == 1, j
PY
if ls "$out"/*.tmp >/dev/null 2>&1; then echo "FAIL: a temporary file was left"; fail=1; fi

[ $fail -eq 0 ] && echo "ok: every bad suite is refused naming its file and JSON path"
exit $fail
