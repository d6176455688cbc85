#!/usr/bin/env bash
# shadowlab-cli bench: one CSV row per configuration with every documented column; on
# plane-box the error is near zero at 4096^2 and rises as the resolution falls; a static
# camera has no flicker; the chart is a valid PNG; bad sweeps exit 2 naming the problem.
# --x ms|bytes: a CSV written without --x charts against memory (`chart --x bytes`), so does
# an older CSV without `pareto_bytes` (docs/images); `pareto_bytes` is the front of memory
# against error; `bench --x bytes` draws the memory chart directly; a bad --x value, or
# --x bytes on a CSV without `bytes`, exits 2 naming it. Omni lights: cube and
# dual-paraboloid on omni-room with exact bytes and their own per-pass columns.
set -euo pipefail
cli=$1 out=$3/bench
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
rm -f "$out"/*.csv "$out"/*.png

# Along plane-box's camera path (3 frames), three resolutions, with the chart. --path-hz 0
# throughout: uniform keeps no state, and the frames in between (tests/cli/path_hz.sh) would
# take this test from seconds to minutes.
"$cli" bench --scene plane-box --technique uniform:resolution=4096,512,64 --frames 3 \
  --path-hz 0 --size 320x180 --csv "$out/path.csv" --chart "$out/path.png" 2>"$out/path.stderr"
# A static bookmark: consecutive frames are identical, so no flicker.
"$cli" bench --scene plane-box --camera overview --technique uniform:resolution=256,1024 \
  --frames 3 --size 320x180 --csv "$out/static.csv" 2>/dev/null

python3 - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/path.csv")))
assert len(rows) == 3, f"expected 3 rows (one per configuration), got {len(rows)}"
need = ["scene", "technique", "params", "frames", "timing_method", "total_ms", "texels", "bytes",
        "error_pct", "false_lit_pct", "false_shadow_pct", "aliasing_mean", "aliasing_p95",
        "aliasing_max", "flicker_pct", "pareto"]
missing = [k for k in need if k not in rows[0]]
assert not missing, f"missing columns {missing}"
assert any(k.endswith("_ms") and k != "total_ms" for k in rows[0]), "no per-pass columns"
for r in rows:  # every frame's total (3 frames): total_ms is the middle one
    per = [float(x) for x in r["total_ms_frames"].split(";")]
    assert len(per) == int(r["frames"]) == 3, r["total_ms_frames"]
    assert sorted(per)[1] == float(r["total_ms"]), (r["total_ms_frames"], r["total_ms"])
by = {r["params"]: r for r in rows}
e = {res: float(by[f"resolution={res}"]["error_pct"]) for res in (4096, 512, 64)}
assert e[4096] < 0.5, f"error at 4096^2 is {e[4096]}%, expected near zero"
assert e[4096] < e[512] < e[64], f"error should rise as the resolution falls: {e}"
m = {res: float(by[f"resolution={res}"]["aliasing_mean"]) for res in (4096, 512, 64)}
assert m[4096] < m[512] < m[64], f"aliasing m should rise as the resolution falls: {m}"
assert int(by["resolution=4096"]["texels"]) == 4096 * 4096
assert all(r["frames"] == "3" for r in rows)

static = list(csv.DictReader(open(f"{out}/static.csv")))
assert len(static) == 2
for r in static:
    assert float(r["flicker_pct"]) == 0.0, f"flicker on a static camera: {r['label']} {r['flicker_pct']}"
print(f"ok: error_pct {e}, aliasing_mean {m}")
PY
grep -q "left" "$out/path.stderr" || { echo "FAIL: no progress/time-left line on stderr"; exit 1; }

# Omni lights (point light of omni-room): cube at 64^2 and 128^2 per face, dual-paraboloid at
# 64^2 per hemisphere, one frame each. Every row measured (finite error and m), its bytes
# exactly the maps' (4 B x resolution^2 x 6 faces or 2 hemispheres), its own pass timed
# (cube_faces_ms, paraboloid_halves_ms) and the other technique's pass column empty.
"$cli" bench --scene omni-room --technique cube:resolution=64,128 \
  --technique dual-paraboloid:resolution=64 --frames 1 --size 160x90 --csv "$out/omni.csv" \
  2>/dev/null
python3 - "$out" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(f"{sys.argv[1]}/omni.csv")))
by = {(r["technique"], r["params"]): r for r in rows}
want = {("cube", "resolution=64"): (6, 64, "cube_faces_ms", "paraboloid_halves_ms"),
        ("cube", "resolution=128"): (6, 128, "cube_faces_ms", "paraboloid_halves_ms"),
        ("dual-paraboloid", "resolution=64"): (2, 64, "paraboloid_halves_ms", "cube_faces_ms")}
assert len(rows) == 3 and set(by) == set(want), f"rows {sorted(by)}"
for key, (maps, res, own, other) in want.items():
    r = by[key]
    for k in ("error_pct", "aliasing_mean", "aliasing_p95", "aliasing_max"):
        v = float(r[k])
        assert math.isfinite(v) and v >= 0, f"{key} {k} = {r[k]}"
    assert float(r["aliasing_max"]) > 0, f"{key}: no aliasing measured"
    assert int(r["bytes"]) == 4 * res * res * maps, f"{key} bytes {r['bytes']}"
    assert int(r["texels"]) == res * res * maps, f"{key} texels {r['texels']}"
    assert r[own] != "" and float(r[own]) >= 0, f"{key}: pass column {own} = '{r[own]}'"
    assert r[other] == "", f"{key}: {other} = '{r[other]}' (not its pass)"
print(f"ok: omni rows {[(k, by[k]['error_pct'], by[k]['bytes']) for k in want]}")
PY

# x: memory. A sweep where the fronts differ (RTW small but slow), charted after the run.
"$cli" bench --scene plane-box --technique uniform:resolution=256,1024 \
  --technique rtw-backward:resolution=256 --frames 2 --warmup 1 --path-hz 0 --size 320x180 \
  --csv "$out/sweep.csv" --chart "$out/ms.png" 2>/dev/null
"$cli" chart --csv "$out/sweep.csv" --chart "$out/bytes.png" --x bytes
"$cli" chart --csv "$here/../../docs/images/bench-diagonal.csv" --chart "$out/old.png" --x bytes
"$cli" bench --scene plane-box --technique uniform:resolution=256,512 --frames 2 --warmup 1 \
  --path-hz 0 --size 320x180 --csv "$out/direct.csv" --chart "$out/direct.png" --x bytes 2>/dev/null

python3 - "$out" <<'PY'
import csv, struct, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/sweep.csv")))
assert len(rows) == 3, f"expected 3 rows, got {len(rows)}"
for k in ("bytes", "pareto", "pareto_bytes"):
    assert k in rows[0], f"no column {k}"
# The front of memory against error, recomputed from the CSV: nothing else at most as big
# and at most as wrong and strictly better in one.
def front(cost):
    pts = [(cost(r), float(r["error_pct"])) for r in rows]
    return [int(not any(q[0] <= p[0] and q[1] <= p[1] and q != p for q in pts)) for p in pts]
want = front(lambda r: int(r["bytes"]))
got = [int(r["pareto_bytes"]) for r in rows]
assert got == want, f"pareto_bytes {got}, expected {want} from bytes/error_pct"
assert [int(r["pareto"]) for r in rows] == front(lambda r: float(r["total_ms"])), "pareto (ms)"
by = {r["label"]: int(r["bytes"]) for r in rows}
assert by["uniform resolution=1024"] == 16 * by["uniform resolution=256"], by

def png(name):  # every chart: a 1280x800 PNG with content
    data = open(f"{out}/{name}", "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR", f"{name} is not a PNG"
    w, h = struct.unpack(">II", data[16:24])
    assert (w, h) == (1280, 800), f"{name} is {w}x{h}"
    assert len(data) > 20000, f"{name} is suspiciously small ({len(data)} bytes)"
    return data
assert png("bytes.png") != png("ms.png"), "the memory chart is the time chart"
for name in ("path.png", "old.png", "direct.png"):
    png(name)
print(f"ok: pareto_bytes {got}, bytes {by}, 5 charts")
PY

# Bad input: exit 2 and one line naming the problem.
expect() {  # expect "substring" args...
  local want=$1; shift
  local err rc=0
  err=$("$cli" "$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -ne 2 ]; then echo "FAIL (exit $rc, expected 2): $*"; exit 1; fi
  if [[ "$err" != *"$want"* ]]; then echo "FAIL: '$*' said '$err', expected '$want'"; exit 1; fi
  echo "ok: $err"
}
expect "unknown technique 'nope'" bench --scene plane-box --technique nope --csv "$out/x.csv"
expect "no parameter 'bogus'" bench --scene plane-box --technique uniform:bogus=1,2 --csv "$out/x.csv"
expect "64..16384" bench --scene plane-box --technique uniform:resolution=32,64 --csv "$out/x.csv"
expect "--csv" bench --scene plane-box --technique uniform
expect "no camera path 'nope'" bench --scene plane-box --technique uniform --path nope --csv "$out/x.csv"
expect "--x: expected ms or bytes, got 'foo'" chart --csv "$out/sweep.csv" --chart "$out/x.png" --x foo
expect "--x: expected ms or bytes, got 'foo'" bench --scene plane-box --technique uniform \
  --csv "$out/x.csv" --x foo
python3 - "$out" <<'PY'
import csv, sys
out = sys.argv[1]
rows = list(csv.reader(open(f"{out}/sweep.csv")))
i = rows[0].index("bytes")
csv.writer(open(f"{out}/nobytes.csv", "w", newline="")).writerows(r[:i] + r[i + 1:] for r in rows)
PY
expect "no column 'bytes'" chart --csv "$out/nobytes.csv" --chart "$out/x.png" --x bytes
"$cli" chart --csv "$out/nobytes.csv" --chart "$out/nobytes-ms.png" >/dev/null  # time: fine
test -s "$out/nobytes-ms.png"
