#!/usr/bin/env bash
# shadowlab-cli stability --suite: the failure-case suite (scenes/suites/failure-cases.json)
# at a tenth of its frames passes; a failing expectation exits 1 naming its case; an
# optional technique that is not registered is skipped, saying so; a bad suite file exits 2
# naming the problem (every bad-input fixture: tests/cli/suite_input.sh).
set -uo pipefail
cli=$1 out=$3/suite
here=$(cd "$(dirname "$0")" && pwd)
suites=$here/../../scenes/suites
mkdir -p "$out"
fail=0

"$cli" stability --suite "$suites/failure-cases.json" --frames-scale 0.1 \
  --json "$out/failure-cases.json" >"$out/failure-cases.txt" 2>"$out/failure-cases.stderr"
rc=$?
if [ $rc -ne 0 ]; then
  echo "FAIL: failure-cases suite exited $rc"; cat "$out/failure-cases.txt" "$out/failure-cases.stderr"
  fail=1
else
  tail -n 1 "$out/failure-cases.txt" | grep -q . && grep "expectations passed" "$out/failure-cases.txt"
fi

# A suite whose expectation must fail, and an optional technique that does not exist.
cat >"$out/must-fail.json" <<'JSON'
{
  "name": "must-fail",
  "size": [160, 90],
  "cases": [
    {"name": "static-uniform-must-fail", "scene": "plane-box", "camera": "overview",
     "motion": "static", "frames": 3,
     "techniques": ["uniform", {"id": "no-such-technique", "optional": true}],
     "expect": [
       {"technique": "uniform", "metric": "mask_change_frames", "op": ">", "value": 0},
       {"technique": "no-such-technique", "metric": "error_pct", "op": "<", "value": 1},
       {"technique": "uniform", "metric": "error_pct", "op": "<", "value": 100}
     ]}
  ]
}
JSON
stdout=$("$cli" stability --suite "$out/must-fail.json" --json "$out/must-fail.out.json" 2>"$out/must-fail.stderr")
rc=$?
if [ $rc -ne 1 ]; then echo "FAIL: a failing expectation exited $rc, expected 1"; fail=1; fi
if ! grep -q "FAILED case 'static-uniform-must-fail'" "$out/must-fail.stderr"; then
  echo "FAIL: stderr does not name the failing case:"; cat "$out/must-fail.stderr"; fail=1
fi
if [[ "$stdout" != *"skipped: technique no-such-technique not available (optional)"* ]]; then
  echo "FAIL: no 'skipped: technique no-such-technique not available (optional)' line:"
  echo "$stdout"; fail=1
fi
python3 - "$out/must-fail.out.json" <<'PY' || fail=1
import json, sys
j = json.load(open(sys.argv[1]))
assert (j["passed"], j["failed"], j["skipped"]) == (1, 1, 1), j
PY

# A bad suite: unknown metric -> exit 2, one line naming it.
cat >"$out/bad.json" <<'JSON'
{"cases": [{"name": "x", "scene": "plane-box", "techniques": ["uniform"],
            "expect": [{"technique": "uniform", "metric": "nonsense", "op": "==", "value": 0}]}]}
JSON
err=$("$cli" stability --suite "$out/bad.json" 2>&1 >/dev/null); rc=$?
if [ $rc -ne 2 ] || [[ "$err" != *"bad.json: cases[0].expect[0].metric: unknown metric 'nonsense'"* ]]; then
  echo "FAIL: bad suite exited $rc saying '$err'"; fail=1
fi
[ $fail -eq 0 ] && echo "ok: suite passes, failures are named, bad suites are refused"
exit $fail
