#!/usr/bin/env bash
# bench --path-hz: along a camera path each configuration renders a frame every 1/HZ s of path
# time between the measured frames (default 30, 0 for none), the reference is traced at the
# measured frames only, and the CSV's path_hz says the spacing (empty with a fixed camera). A
# stateless technique measures the same at any rate (the measured cameras do not move). Bad
# values exit 2 with one line naming --path-hz.
set -euo pipefail
cli=$1 out=$3/path_hz
mkdir -p "$out"
rm -f "$out"/*.csv "$out"/*.txt

# plane-box's path lasts 10 s: 2 frames at 0 and 10 s, so at 4 Hz 39 frames in between.
run() {  # run NAME args...
  local name=$1; shift
  "$cli" bench --scene plane-box --technique uniform:resolution=256 --frames 2 --warmup 0 \
    --size 64x36 --csv "$out/$name.csv" "$@" >"$out/$name.txt" 2>"$out/$name.stderr"
}
run hz4 --path-hz 4
run hz0 --path-hz 0
run default
run fixed --camera overview

says() {  # says NAME "text"
  grep -qF -- "$2" "$out/$1.txt" || { echo "FAIL: $1: no '$2' in:"; cat "$out/$1.txt"; exit 1; }
}
says hz4 "41 frames rendered by each configuration"
says hz4 "2 reference evaluations"
says hz4 "4 Hz"
says hz0 "2 frames rendered by each configuration"
says default "301 frames rendered by each configuration"  # 30 Hz: 299 in the 10 s, 2 measured
says default "30 Hz"
says fixed "2 frames rendered by each configuration"
grep -qF "39 unmeasured frames in between" "$out/hz4.stderr" ||
  { echo "FAIL: hz4: stderr does not count the frames in between:"; cat "$out/hz4.stderr"; exit 1; }

python3 - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
row = {n: next(csv.DictReader(open(f"{out}/{n}.csv"))) for n in ("hz4", "hz0", "default", "fixed")}
got = {n: r["path_hz"] for n, r in row.items()}
assert got == {"hz4": "4", "hz0": "0", "default": "30", "fixed": ""}, got
header = next(csv.reader(open(f"{out}/hz4.csv")))
assert header[header.index("frames") + 1] == "path_hz", header
for n, r in row.items():
    assert r["frames"] == "2" and r["render_errors"] == "0", (n, r["frames"], r["render_errors"])
# uniform keeps no state between frames: the same measured cameras, the same error.
assert row["hz4"]["error_pct"] == row["hz0"]["error_pct"] == row["default"]["error_pct"], \
    {n: r["error_pct"] for n, r in row.items()}
print(f"ok: path_hz {got}, error {row['hz4']['error_pct']} % at every rate")
PY
# chart reads the column (the title names the rate).
"$cli" chart --csv "$out/hz4.csv" --chart "$out/hz4.png" >/dev/null
test -s "$out/hz4.png"

expect() {  # expect "substring" args...: exit 2, one line naming it
  local want=$1; shift
  local err rc=0
  err=$("$cli" "$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -ne 2 ]; then echo "FAIL (exit $rc, expected 2): $*"; exit 1; fi
  if [[ "$err" != *"$want"* ]]; then echo "FAIL: '$*' said '$err', expected '$want'"; exit 1; fi
  if [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ]; then echo "FAIL: '$*' said more than a line: $err"; exit 1; fi
  echo "ok: $err"
}
bad=(bench --scene plane-box --technique uniform --csv "$out/x.csv")
expect "--path-hz: 241 is out of range 0..240" "${bad[@]}" --path-hz 241
expect "--path-hz: -1 is out of range 0..240" "${bad[@]}" --path-hz -1
expect "--path-hz: expected a number, got 'fast'" "${bad[@]}" --path-hz fast
expect "--path-hz: nan is not a finite number" "${bad[@]}" --path-hz nan
expect "--path-hz: missing value" "${bad[@]}" --path-hz
expect "--path-hz: goes with a camera path, not --camera" "${bad[@]}" --camera overview --path-hz 30
test ! -e "$out/x.csv"
echo "PASS: path_hz"
