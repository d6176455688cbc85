#!/usr/bin/env bash
# The GUI never shows 0 % for an error it did not measure: a view that sees only sky (no
# covered pixel) and a light the technique refuses (the frame fails) are grabbed; the status
# line reads "error n/a (...)" (published.json's error_readout) and the grab's published.json has
# error_pct null with the reason (and frame_failure, frame_ms null and the Timing panel's
# "total n/a (the frame failed: ...)" for the failed frame), never 0. The refused light is a problem of the
# grab: it exits 1 (it exited 0); the sky is not: 0.
# usage: unmeasured_error.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1 data=$2
out=$3/unmeasured_error
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

for case in sky refused-light; do
  rc=0
  timeout 300 "$app" --lesson "$data/presets/unmeasured-$case.json" --grab "$out/$case" \
    --grab-after 3 >"$out/$case.stdout" 2>"$out/$case.stderr" || rc=$?
  # A refused light is a problem the grab reports: it exits 1 (the sky is no problem: 0); the
  # grab's files are there either way.
  want=0
  [[ $case == refused-light ]] && want=1
  [[ $rc -eq $want ]] || { echo "FAIL: $case: exit $rc, expected $want"; cat "$out/$case.stderr"; exit 1; }
  [[ -s "$out/$case/published.json" ]] ||
    { echo "FAIL: $case: no published.json (exit $rc)"; cat "$out/$case.stderr"; exit 1; }
  python3 - "$case" "$out/$case/published.json" <<'PY'
import json, sys
case, path = sys.argv[1], sys.argv[2]
p = json.load(open(path))
assert "error_pct" in p, f"{case}: error_pct missing (the error was not evaluated): {sorted(p)}"
assert p["error_pct"] is None, f"{case}: error_pct is {p['error_pct']!r}, not null"
why = p.get("error_unmeasured", "")
if case == "sky":
    assert why == "no covered pixel", f"sky: error_unmeasured {why!r}"
else:
    assert why.startswith("the frame failed"), f"refused light: error_unmeasured {why!r}"
    assert "point light" in p.get("frame_failure", ""), f"frame_failure {p.get('frame_failure')!r}"
readout = p.get("error_readout", "")
assert readout.startswith("error n/a (") and why.split(":")[0] in readout, \
    f"{case}: the status line read {readout!r}"
assert "0.000" not in readout and "%" not in readout, f"{case}: {readout!r}"
timing = p.get("timing_summary", "")
if case == "sky":
    assert isinstance(p.get("frame_ms"), (int, float)), f"sky: frame_ms {p.get('frame_ms')!r}"
    assert "n/a" not in timing, f"sky: the Timing panel read {timing!r}"
else:
    assert p.get("frame_ms", 0) is None, f"refused light: frame_ms {p.get('frame_ms')!r}, not null"
    assert "total <b>n/a</b> (the frame failed: " in timing and "point light" in timing, \
        f"refused light: the Timing panel read {timing!r}"
print(f"{case}: error_pct null, {why}; status line {readout!r}; frame_ms {p.get('frame_ms')!r}")
PY
done
echo "PASS"
