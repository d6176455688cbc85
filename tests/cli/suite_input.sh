#!/usr/bin/env bash
# Suites that cannot pass by accident (issue 14): a case that ran no configuration fails
# (exit 1); a case that throws leaves the cases run before it in the --json file. The suites
# refused at load (misspelt ids and keys, bad values) are hostile fixtures:
# tests/fixtures/hostile/suite-*.json, checked by cli.hostile_fixtures.
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
expect_error only-optional.json 1 \
  "$p: FAILED case 'nothing-runs': the case runs at least one configuration (ran none: every technique was skipped)"
expect_error later-case-fails.json 2 \
  "$p: later-case-fails.json: cases[1] (case 'second'): camera: scene 'plane-box' has no camera 'no-such-bookmark' *"

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
