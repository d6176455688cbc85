#!/usr/bin/env bash
# The GUI on corridor with cascades and the partition overlay: the Partitions panel draws
# every partition's map with its split distances, its frustum slice and its pixels' m
# (published.json: what the panel drew),
# the splits chain from near to far, and the panel and view PNGs are real pictures.
# usage: grab_cascades.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_cascades
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 300 "$app" --scene corridor --technique cascades --set view.overlay=partition \
  --set partitions=3 --grab "$out" --grab-after 6 >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab exited with $rc; stderr:"
  cat "$out/stderr.txt"
  exit 1
fi
[[ -s "$out/panel-partitions.png" ]] || { echo "FAIL: panel-partitions.png missing"; exit 1; }
python3 "$here/pngstats.py" --min-colors 16 --min-stddev 8 "$out/panel-partitions.png"
python3 "$here/pngstats.py" --min-colors 32 --min-stddev 8 "$out/viewport.png"
python3 - "$out/published.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
p = d["panels"]["partitions"]
assert p["partitions"] == 3, p
parts = p["parts"]
assert len(parts) == 3, parts
assert abs(parts[0]["near_m"] - p["depth_near_m"]) < 1e-9 and abs(parts[-1]["far_m"] - p["depth_far_m"]) < 1e-9, p
for a, b in zip(parts, parts[1:]):
    assert abs(a["far_m"] - b["near_m"]) < 1e-9, (a, b)
    assert a["texels_per_m"] > b["texels_per_m"], (a, b)  # near partitions: finer texels
for q in parts:
    assert q["map_published"] and q["far_m"] > q["near_m"] and q["texels"] > 0, q
    # Its frustum slice drawn on its map (the 12 edges of the slice, clipped) and its pixels' m.
    assert q["slice_segments"] >= 4, q
    # (p95 is read from 1/8-octave bins: at most one bin above the exact maximum.)
    assert q["m_pixels"] > 0 and 0 < q["m_p95"] <= q["m_max"] * 2 ** 0.125, q
print("partitions panel:", [(round(q["near_m"], 3), round(q["far_m"], 3)) for q in parts])
PY
echo "PASS"
