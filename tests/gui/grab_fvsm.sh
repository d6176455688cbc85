#!/usr/bin/env bash
# The GUI on plane-box with fvsm: the FVSM panel draws each kd leaf's screen rectangle over the
# camera's image and the kd leaves over the light's view (depth), the SMTMM's needs along both
# SM axes as heat maps with the rectangles over them, the tile grid with the kd leaves over it, the neediest cell's histogram, the tiles' textures and times, and the frame's
# kd-tree numbers (a real picture; published.json: what it drew, checked for consistency).
# usage: grab_fvsm.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_fvsm
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

rc=0
timeout 300 "$app" --scene plane-box --technique fvsm --set fvsm.max_texture=256 \
  --set fvsm.fallback.resolution=256 --set fvsm.xi=0 --grab "$out/fvsm" --grab-after 3 \
  >"$out/fvsm.stdout" 2>"$out/fvsm.stderr" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab (fvsm) exited with $rc; stderr:"
  cat "$out/fvsm.stderr"
  exit 1
fi
python3 "$here/pngstats.py" --min-colors 16 --min-stddev 8 "$out/fvsm/panel-fvsm.png"
python3 - "$out" <<'PY'
import json, sys
p = json.load(open(f"{sys.argv[1]}/fvsm/published.json"))["panels"]["fvsm"]
assert p["tiles"] >= 1 and p["max_entry_need"] >= 1, p
assert p["need_u"] >= 0 and p["need_v"] >= 0, p
# Every leaf the renderer counted is drawn over the grid, each with a screen rectangle.
assert p["leaves_drawn"] == p["tiles"], p
assert 1 <= p["rects_drawn"] <= p["leaves_drawn"], p
assert p["grid_n"] == 32 and p["texture_kinds"] >= 1, p
# The issue's two views: the rectangles over the camera image (the frame's aspect, its longer
# side 256 texels, some with a surface), the leaves over the light's view (256², some
# geometry nearer than the far plane).
assert max(p["camera_w"], p["camera_h"]) == 256 and min(p["camera_w"], p["camera_h"]) >= 1, p
assert p["camera_rects_drawn"] == p["rects_drawn"], p
assert 0 < p["camera_surface_texels"] < p["camera_w"] * p["camera_h"], p
assert (p["light_w"], p["light_h"]) == (256, 256), p
assert p["light_leaves_drawn"] == p["tiles"], p
assert 0 < p["light_geometry_texels"] <= 256 * 256, p
# Each leaf's depth and apply time (fvsm.tile_ms) is listed, and they took some time.
assert p["tile_times_listed"] == p["tiles"] and p["tile_ms_sum"] > 0, p
# The histogram drawn is a real cell's: its buckets count each of its entries once per axis.
assert p["cell_entries"] >= 1, p
assert p["hist_u_total"] == p["cell_entries"] == p["hist_v_total"], p
print(f"ok: fvsm panel: {p['tiles']:.0f} kd leaves ({p['rects_drawn']:.0f} screen rectangles, "
      f"{p['texture_kinds']:.0f} texture kinds), needs up to 2^{p['max_entry_need']:.0f}, "
      f"cell ({p['cell_x']}, {p['cell_y']}) histogram of {p['cell_entries']:.0f} entries")
PY
