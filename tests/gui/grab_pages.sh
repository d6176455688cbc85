#!/usr/bin/env bash
# The GUI on plane-box with rmsm and a pool too small for the frame (8 pages): the Pages
# panel draws the page table with its counts (published.json: what the panel drew: 8 levels,
# every pool page used, requests coarsened), and its PNG is a real picture.
# usage: grab_pages.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_pages
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 300 "$app" --scene plane-box --technique rmsm --set virtual.resolution=16384 \
  --set pool.pages=8 --grab "$out/rmsm" --grab-after 3 >"$out/rmsm.stdout" \
  2>"$out/rmsm.stderr" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab (rmsm) exited with $rc; stderr:"
  cat "$out/rmsm.stderr"
  exit 1
fi
python3 "$here/pngstats.py" --min-colors 3 --min-stddev 8 "$out/rmsm/panel-pages.png"
python3 - "$out" <<'PY'
import json, sys
p = json.load(open(f"{sys.argv[1]}/rmsm/published.json"))["panels"]["pages"]
assert p["levels"] == 8 and p["pool"] == 8 and p["allocated"] <= 8, p
assert p["requested"] > 8 and p["coarsened"] > 0, p
print("ok: pages panel: 8 levels, pool of 8 used, %d requests coarsened" % p["coarsened"])
PY
