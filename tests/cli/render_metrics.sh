#!/usr/bin/env bash
# shadowlab-cli render: plane-box with uniform at 4096^2 is within 0.5 % of the exact
# reference, and the metrics JSON holds every documented field.
set -euo pipefail
cli=$1 out=$3
mkdir -p "$out"
"$cli" render --scene plane-box --technique uniform --set resolution=4096 --size 640x360 \
  --out "$out/pb.png" --metrics "$out/pb.json" --error-image "$out/pb-error.png"
test -s "$out/pb.png" && test -s "$out/pb-error.png"
python3 - "$out/pb.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
need = ["technique", "params", "size", "total_ms", "passes", "texels", "bytes", "error_pct",
        "false_lit_pct", "false_shadow_pct", "timing_method"]
missing = [k for k in need if k not in m]
assert not missing, f"missing keys {missing}"
assert m["technique"] == "uniform" and m["params"]["resolution"] == "4096"
assert m["size"] == [640, 360]
assert m["texels"] == 4096 * 4096, m["texels"]
assert isinstance(m["published"], dict), m["published"]  # the technique's numbers
assert all("ms" in p and "method" in p for p in m["passes"]), m["passes"]
assert m["error_pct"] < 0.5, f"error_pct {m['error_pct']}"
assert abs(m["error_pct"] - m["false_lit_pct"] - m["false_shadow_pct"]) < 1e-9
print(f"ok: error_pct={m['error_pct']:.4f} total_ms={m['total_ms']:.1f} ({m['timing_method']})")
PY

# A published number that is not finite is named, never null (which reads as "not measured"):
# lispsm falls back to the orthographic map with the sun at 5 degrees on corridor, n' infinite.
"$cli" render --scene corridor --technique lispsm --light 0,5 --size 64x36 \
  --out "$out/fallback.png" --metrics "$out/fallback.json" >/dev/null
python3 - "$out/fallback.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["published"]
assert p["warp.fallback"] == 1, p
assert p["warp.n_prime"] == "inf", p
assert all(v is not None for v in p.values()), p
print("ok: warp.n_prime", p["warp.n_prime"], "on a fallback")
PY
