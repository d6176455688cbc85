#!/usr/bin/env bash
# shadowlab-cli render --wrong-pixels: one CSV line per pixel whose hard test disagrees with
# the exact reference — as many lines as the metrics count, each false-lit / false-shadow as
# counted, inside the frame, on a surface (unit normal), with the map and uv the lookup used.
set -euo pipefail
cli=$1 out=$3/render-wrong-pixels
rm -rf "$out" && mkdir -p "$out"
"$cli" render --scene plane-box --technique uniform --set resolution=128 --size 320x180 \
  --out "$out/pb.png" --metrics "$out/pb.json" --wrong-pixels "$out/pb.csv" >/dev/null
python3 - "$out/pb.json" "$out/pb.csv" <<'PY'
import csv, json, math, sys
m = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
assert list(rows[0].keys()) == ["x", "y", "wrong", "px", "py", "pz", "nx", "ny", "nz", "m", "map",
                                "u", "v"], rows[0].keys()
lit = sum(r["wrong"] == "false_lit" for r in rows)
shadow = sum(r["wrong"] == "false_shadow" for r in rows)
assert lit + shadow == len(rows), "every line is false_lit or false_shadow"
covered = m["covered_pixels"]
assert len(rows) >= 10, f"a 128² map at 320x180 has wrong pixels, got {len(rows)}"
assert round(m["false_lit_pct"] * covered / 100) == lit, (m["false_lit_pct"], lit)
assert round(m["false_shadow_pct"] * covered / 100) == shadow, (m["false_shadow_pct"], shadow)
pixels = set()
for r in rows:
    x, y = int(r["x"]), int(r["y"])
    assert 0 <= x < 320 and 0 <= y < 180, (x, y)
    pixels.add((x, y))
    n = math.sqrt(sum(float(r[k]) ** 2 for k in ("nx", "ny", "nz")))
    assert abs(n - 1) < 1e-3, r
    assert float(r["m"]) > 0 and r["map"] == "0", r
    assert -0.5 <= float(r["u"]) <= 1.5 and -0.5 <= float(r["v"]) <= 1.5, r
assert len(pixels) == len(rows), "each pixel once"
print(f"ok: {len(rows)} wrong pixels ({lit} false lit, {shadow} false shadow), as counted")
PY
