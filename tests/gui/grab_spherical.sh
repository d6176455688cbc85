#!/usr/bin/env bash
# The GUI on omni-room with the spherical technique: the Spherical map panel draws the whole
# latitude-longitude map (two halves side by side, seam and poles marked; published.json:
# what the panel drew): a real picture, and the pole ratio it states is cot(pi / 2H).
# usage: grab_spherical.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_spherical
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 300 "$app" --scene omni-room --technique spherical --set resolution=256 \
  --grab "$out/spherical" --grab-after 3 >"$out/spherical.stdout" 2>"$out/spherical.stderr" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab exited with $rc; stderr:"
  cat "$out/spherical.stderr"
  exit 1
fi
python3 "$here/pngstats.py" --min-colors 16 --min-stddev 8 "$out/spherical/panel-spherical.png"
python3 - "$out" <<'PY'
import json, math, sys
out = sys.argv[1]
p = json.load(open(f"{out}/spherical/published.json"))["panels"]["spherical"]
assert p["kind"] == "latlong" and p["maps"] == 2 and p["resolution"] == 256, p
assert abs(p["pole_ratio_analytic"] - 1 / math.tan(math.pi / 512)) < 1e-9, p
print("ok: spherical panel: 2 halves of 256, pole ratio", p["pole_ratio_analytic"])
PY
echo "PASS"
