#!/usr/bin/env bash
# The GUI on omni-room: the Omni map panel draws the cube as an unfolded cross (six faces)
# and the dual paraboloid as two discs (published.json: what the panel drew); both PNGs are
# real pictures. Then its marker (GUI test omni-probe): the mouse over the view puts it on
# the face (cube) or hemisphere and uv that algo/omni computes for the pixel's direction from
# the light; leaving the view removes it.
# usage: grab_omni.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/grab_omni
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

for t in cube dual-paraboloid; do
  rc=0
  timeout 300 "$app" --scene omni-room --technique $t --set resolution=256 --grab "$out/$t" \
    --grab-after 3 >"$out/$t.stdout" 2>"$out/$t.stderr" || rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "FAIL: shadowlab ($t) exited with $rc; stderr:"
    cat "$out/$t.stderr"
    exit 1
  fi
  python3 "$here/pngstats.py" --min-colors 16 --min-stddev 8 "$out/$t/panel-omni.png"
done
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
cube = json.load(open(f"{out}/cube/published.json"))["panels"]["omni"]
assert cube["kind"] == "cube" and cube["maps"] == 6 and cube["resolution"] == 256, cube
assert abs(cube["density_ratio_analytic"] - 27 ** 0.5) < 1e-9, cube
dp = json.load(open(f"{out}/dual-paraboloid/published.json"))["panels"]["omni"]
assert dp["kind"] == "paraboloid" and dp["maps"] == 2 and dp["density_ratio_analytic"] == 4, dp
print("ok: omni panel: cube cross of 6 faces, paraboloid 2 discs")
PY

for t in cube dual-paraboloid; do
  echo "[marker: $t]"
  run_gui_test "GUI test omni-probe ($t)" 240 "$out/probe-$t" "$tests" --scene omni-room \
    --technique $t --set resolution=256 --set bias.normal=0 --test "omni-probe=$out/probe-$t"
  [[ $(grep -c "^ok   pixel" "$out/probe-$t.stdout") -ge 3 ]] || { echo "FAIL: under 3 pixels checked"; exit 1; }
  python3 "$here/pngstats.py" --min-colors 16 --min-stddev 8 "$out/probe-$t/omni-probe.png"
done
echo "PASS"
