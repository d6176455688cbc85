#!/usr/bin/env bash
# shadowlab-cli bench: one CSV row per configuration with every documented column; on
# plane-box the error is near zero at 4096^2 and rises as the resolution falls; a static
# camera has no flicker; the chart is a valid PNG; bad sweeps exit 2 naming the problem.
set -euo pipefail
cli=$1 out=$3/bench
mkdir -p "$out"
rm -f "$out"/*.csv "$out"/*.png

# Along plane-box's camera path (3 frames), three resolutions, with the chart.
"$cli" bench --scene plane-box --technique uniform:resolution=4096,512,64 --frames 3 \
  --size 320x180 --csv "$out/path.csv" --chart "$out/path.png" 2>"$out/path.stderr"
# A static bookmark: consecutive frames are identical, so no flicker.
"$cli" bench --scene plane-box --camera overview --technique uniform:resolution=256,1024 \
  --frames 3 --size 320x180 --csv "$out/static.csv" 2>/dev/null

python3 - "$out" <<'PY'
import csv, struct, sys
out = sys.argv[1]
rows = list(csv.DictReader(open(f"{out}/path.csv")))
assert len(rows) == 3, f"expected 3 rows (one per configuration), got {len(rows)}"
need = ["scene", "technique", "params", "frames", "timing_method", "total_ms", "texels", "bytes",
        "error_pct", "false_lit_pct", "false_shadow_pct", "aliasing_mean", "aliasing_p95",
        "aliasing_max", "flicker_pct", "pareto"]
missing = [k for k in need if k not in rows[0]]
assert not missing, f"missing columns {missing}"
assert any(k.endswith("_ms") and k != "total_ms" for k in rows[0]), "no per-pass columns"
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

png = open(f"{out}/path.png", "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n", "chart is not a PNG"
assert png[12:16] == b"IHDR"
w, h = struct.unpack(">II", png[16:24])
assert (w, h) == (1280, 800), f"chart is {w}x{h}"
assert len(png) > 20000, f"chart is suspiciously small ({len(png)} bytes)"
print(f"ok: error_pct {e}, aliasing_mean {m}, chart {w}x{h} {len(png)} bytes")
PY
grep -q "left" "$out/path.stderr" || { echo "FAIL: no progress/time-left line on stderr"; exit 1; }

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
