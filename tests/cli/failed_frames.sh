#!/usr/bin/env bash
# A failed frame is never a measurement: a frame renderFrame refuses (here a camera 1e30 m
# away) is counted and named, left out of the
# medians and the Pareto fronts; a configuration with no frame that rendered is a failed row
# with empty numbers; bench exits 1 naming it; chart leaves failed rows out; a suite whose
# configuration failed frames fails.
# A spot aimed away from the scene is not a failure: every pixel is shadowed, and measured so.
set -uo pipefail
cli=$1 data=$2 out=$3/failed-frames
rm -rf "$out" && mkdir -p "$out"
fail=0
check() {  # check DESCRIPTION COMMAND...: passes when the command succeeds
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}
cell() {  # cell FILE.csv ROW COLUMN: the value (ROW from 1)
  python3 -c 'import csv,sys; r=list(csv.DictReader(open(sys.argv[1]))); print(r[int(sys.argv[2])-1][sys.argv[3]])' "$@"
}

# camera-path.gltf with its translation keys moved 1e30 m away: finite, but a float there
# cannot tell the camera's target from its position, and renderFrame refuses every camera.
faraway() {  # faraway OUT.gltf
  python3 - "$data/camera-path.gltf" "$1" <<'PY'
import base64, json, struct, sys
g = json.load(open(sys.argv[1]))
head, b64 = g["buffers"][0]["uri"].split(",", 1)
raw = bytearray(base64.b64decode(b64))
for k in range(3):  # translation keys: 3 VEC3 floats from byte 72
    raw[72 + 12 * k:84 + 12 * k] = struct.pack("<3f", 1e30, 1e30, 1e30)
g["buffers"][0]["uri"] = head + "," + base64.b64encode(bytes(raw)).decode()
json.dump(g, open(sys.argv[2], "w"))
PY
}
faraway "$out/every-frame-fails.gltf"

# 1. Every frame fails: a failed row, every number empty, exit 1 naming it; chart refuses
#    a CSV with nothing measured, and leaves a failed row out of a mixed one.
"$cli" bench --scene "$out/every-frame-fails.gltf" --path dolly --light 30,45 \
  --technique uniform --frames 2 --warmup 0 --size 64x36 \
  --csv "$out/failed.csv" >"$out/failed.txt" 2>"$out/failed.stderr"
check "failed: bench exits 1" test $? -eq 1
for c in total_ms bytes texels error_pct covered_pixels aliasing_mean timing_method; do
  check "failed: $c empty" test -z "$(cell "$out/failed.csv" 1 $c)"
done
check "failed: pareto 0" test "$(cell "$out/failed.csv" 1 pareto)" == 0
check "failed: the failure names frame 0" \
  test "$(cell "$out/failed.csv" 1 failure)" == "frame 0: camera: position equals target"
check "failed: stderr names it" grep -q "^shadowlab-cli: uniform: failed every frame (2): frame 0: camera" \
  "$out/failed.stderr"
check "failed: the table says failed" grep -q "^uniform .*failed: frame 0" "$out/failed.txt"
"$cli" chart --csv "$out/failed.csv" --chart "$out/failed.png" 2>"$out/chart-failed.stderr"
check "chart of a failed row only: exit 2" test $? -eq 2
check "chart says why" grep -q "no row has a measured error_pct (1 failed)" "$out/chart-failed.stderr"
check "chart of a failed row only: no PNG" test ! -e "$out/failed.png"
"$cli" bench --scene plane-box --technique uniform --frames 2 --warmup 0 --size 64x36 \
  --csv "$out/good.csv" >/dev/null 2>&1
check "good: bench exits 0" test $? -eq 0
python3 - "$out/failed.csv" "$out/good.csv" "$out/mixed.csv" <<'PY'
import csv, sys
failed, good = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
w = csv.DictWriter(open(sys.argv[3], "w", newline=""), fieldnames=list(failed[0]),
                   extrasaction="ignore", lineterminator="\n")
w.writeheader()
w.writerows(failed + good)
PY
"$cli" chart --csv "$out/mixed.csv" --chart "$out/mixed.png" >/dev/null 2>"$out/chart-mixed.stderr"
check "chart of a mixed CSV: exit 0" test $? -eq 0
check "chart lists the failed row apart, naming it" grep -q "1 failed configuration not charted: uniform$" "$out/chart-mixed.stderr"
# A chart the disk cannot hold is a write error (exit 1 naming the file), not a silent success.
"$cli" chart --csv "$out/mixed.csv" --chart /dev/full >/dev/null 2>"$out/chart-full.stderr"
check "chart to a full disk: exit 1" test $? -eq 1
check "chart to a full disk: names the file" grep -qF "/dev/full: cannot write (No space left on device)" "$out/chart-full.stderr"

# compare: a configuration that fails is a row saying so (no image), the others go on, exit 1.
"$cli" compare --scene "$out/every-frame-fails.gltf" --path dolly --light 30,45 \
  --technique uniform --size 64x36 --out-dir "$out/compare" >"$out/compare.txt" 2>&1
check "compare: exit 1" test $? -eq 1
check "compare: the row says failed" grep -q "^uniform  *failed: frame 0: camera: position equals target" \
  "$out/compare.txt"
check "compare: no image of a failed configuration" test ! -e "$out/compare/uniform.png"
check "compare: summary.json names the failure" python3 -c '
import json, sys
s = json.load(open(sys.argv[1]))
assert s == [{"configuration": "uniform", "failure": "frame 0: camera: position equals target"}], s
' "$out/compare/summary.json"

# 2. A suite along that path (an orbit of 1e308 degrees a frame did it; orbits are bounded now):
#    the case fails, the first failed frame named.
cat >"$out/orbit.json" <<JSON
{"size": [64, 36],
 "cases": [{"name": "path-out-of-range", "scene": "$out/every-frame-fails.gltf", "motion": "path",
            "path": "dolly", "light": {"azimuth_deg": 30, "elevation_deg": 45},
            "frames": 3, "warmup_frames": 0,
            "techniques": ["uniform"],
            "expect": [{"technique": "uniform", "metric": "gl_errors", "op": "==", "value": 0},
                       {"technique": "uniform", "metric": "total_ms", "op": ">", "value": 0}]}]}
JSON
"$cli" stability --suite "$out/orbit.json" --json "$out/orbit-out.json" >"$out/orbit.txt" 2>&1
check "suite: exits 1" test $? -eq 1
check "suite: the configuration fails, frame 0 named" \
  grep -q "FAIL: uniform renders every frame (3 of 3 frames failed, first frame 0: camera" "$out/orbit.txt"
check "suite: an expectation on the failed configuration fails" \
  grep -q "FAIL: uniform total_ms > 0" "$out/orbit.txt"
check "suite: the JSON names the failed configuration and counts its frames" python3 -c '
import json, sys
case = json.load(open(sys.argv[1]))["cases"][0]
t = case["techniques"]["uniform"]
assert t["render_errors"] == 3 and t["failure"].startswith("frame 0: camera"), t
assert case["failed_configurations"][0]["technique"] == "uniform", case
' "$out/orbit-out.json"

# 3. A spot aimed away from the scene lights nothing: every frame renders, all shadowed,
#    and the reference agrees (error 0, pixels covered).
"$cli" bench --scene spot-box --light spot:0,4,0,0,1,0,40 --technique uniform --frames 2 \
  --warmup 0 --size 64x36 --csv "$out/spot-away.csv" >/dev/null 2>"$out/spot-away.stderr"
check "spot aimed away: bench exits 0" test $? -eq 0
check "spot aimed away: no failed frame" test "$(cell "$out/spot-away.csv" 1 render_errors)" == 0
check "spot aimed away: error 0 %" test "$(cell "$out/spot-away.csv" 1 error_pct)" == 0
check "spot aimed away: pixels covered" test "$(cell "$out/spot-away.csv" 1 covered_pixels)" -gt 0
exit $fail
