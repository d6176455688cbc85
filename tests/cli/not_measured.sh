#!/usr/bin/env bash
# "Not measured" is a value, never 0: a stability run of one frame has no mask or rotation
# changes to count (null in its JSON, n/a in its line), nor flicker; bench over one frame has
# an empty flicker cell and prints n/a; a suite whose camera sees only sky (hostile fixture
# suite-sky-only.json) does not pass "aliasing_max < 1", nor does a 64^2 map "beat" the default
# map on aliasing: both expectations are not measured and the case, having checked nothing,
# fails (exit 1).
set -uo pipefail
cli=$1 out=$3/not_measured
here=$(cd "$(dirname "$0")" && pwd)
fixtures=$here/../fixtures/hostile
rm -rf "$out" && mkdir -p "$out"
fail=0

# One frame: nothing to compare.
"$cli" stability --scene plane-box --technique uniform --frames 1 --reference --size 64x36 \
  --json "$out/one.json" >"$out/one.txt" 2>"$out/one.err" || { echo "FAIL: stability exited $?"; fail=1; }
python3 - "$out/one.json" <<'PY' || fail=1
import json, sys
s = json.load(open(sys.argv[1]))["summary"]
for k in ("rotation_changes", "max_rotation_step_deg", "mask_change_frames", "max_mask_changed_pct",
          "flicker_pct", "flicker_pct_max"):
    assert s[k] is None, f"one frame: {k} = {s[k]!r}, not null"
assert s["frames"] == 1 and s["error_pct"] is not None, s
print("ok: one frame: changes and flicker null, error measured")
PY
grep -q "rotation_changes n/a (fewer than 2 frames: nothing to compare), mask_change_frames n/a" \
  "$out/one.txt" || { echo "FAIL: stability line: $(cat "$out/one.txt")"; fail=1; }

# bench over one frame: flicker is an empty cell, n/a on the console.
"$cli" bench --scene plane-box --technique uniform:resolution=256 --frames 1 --warmup 0 \
  --size 64x36 --csv "$out/b.csv" >"$out/b.txt" 2>/dev/null || { echo "FAIL: bench exited $?"; fail=1; }
python3 - "$out/b.csv" <<'PY' || fail=1
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[0]
assert r["flicker_pct"] == "", f"flicker over one frame: {r['flicker_pct']!r}"
assert r["aliasing_mean"] != "" and r["error_pct"] != "", r
print("ok: bench, one frame: flicker_pct empty")
PY
grep -q "n/a" "$out/b.txt" || { echo "FAIL: bench line has no n/a: $(cat "$out/b.txt")"; fail=1; }

# A suite that sees only sky: not measured, and the case fails (it passed with 0).
rc=0
"$cli" stability --suite "$fixtures/suite-sky-only.json" --json "$out/sky.json" \
  >"$out/sky.txt" 2>"$out/sky.err" || rc=$?
[ $rc -eq 1 ] || { echo "FAIL: sky suite exited $rc, expected 1"; cat "$out/sky.txt"; fail=1; }
grep -q "skipped: uniform aliasing_max < 1: not measured (no covered pixel with a shadow-map coordinate)" \
  "$out/sky.txt" || { echo "FAIL: sky: no not-measured line"; cat "$out/sky.txt"; fail=1; }
grep -q "skipped: uniform 64 aliasing_mean < uniform aliasing_mean: not measured" "$out/sky.txt" ||
  { echo "FAIL: sky: the pair was not skipped as not measured"; cat "$out/sky.txt"; fail=1; }
grep -q "FAIL: the case checks at least one of its expectations" "$out/sky.txt" ||
  { echo "FAIL: sky: the case did not fail"; fail=1; }
python3 - "$out/sky.json" <<'PY' || fail=1
import json, sys
j = json.load(open(sys.argv[1]))
for label in ("uniform", "uniform 64"):
    t = j["cases"][0]["techniques"][label]
    assert t["aliasing_max"] is None and t["aliasing_mean"] is None and t["error_pct"] is None, t
assert j["passed"] == 0, j["passed"]
assert [e["status"] for e in j["cases"][0]["expectations"]][:2] == ["skipped", "skipped"], j["cases"][0]
print("ok: sky suite: aliasing and error null, nothing passed")
PY
[ $fail -eq 0 ] && echo "ok: not measured"
exit $fail
