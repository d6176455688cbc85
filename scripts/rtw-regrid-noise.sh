#!/usr/bin/env bash
# How much a turn changes the error by itself: DA-RTW with the turn fixed at 0, 1, 2, 3 and
# 4 degrees, one frame of each still view (every camera bookmark) at 640x360. Turns that
# small change no texel's size (the frustum's area by < 1 %), only where every shadow edge
# falls against the texel grid; the spread of their errors is what any turn's error carries on
# top of what it gains. scripts/rtw-regrid-noise.py summarises it (docs/results/rtw-rotation.md).
# Usage: scripts/rtw-regrid-noise.sh OUTDIR [RESOLUTION] [SCENE...]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: scripts/rtw-regrid-noise.sh OUTDIR [RESOLUTION] [SCENE...]}
res=${2:-1024}
shift $(($# >= 2 ? 2 : 1))
cli=${SHADOWLAB_CLI:-build/app/shadowlab-cli}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(band-aligned diagonal corridor default blob plane-box thin-pole
  dueling helmet sunroom figure car)
mkdir -p "$out"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene")
  name=${name%.*}
  for i in 0 1 2 3 4 5 6 7; do
    "$cli" render --scene "$scene" --camera "$i" --technique uniform --size 16x16 --no-reference \
      --out "$out/.probe.png" >/dev/null 2>&1 || break
    echo "== $name@$i" >&2
    "$cli" bench --scene "$scene" --camera "$i" --frames 1 --warmup 1 --size 640x360 \
      --technique "da-rtw:resolution=$res:rotation.mode=fixed:rotation.fixed_deg=0,1,2,3,4" \
      --csv "$out/regrid-$name@$i-$res.csv" >"$out/regrid-$name@$i-$res.log" 2>&1 ||
      echo "bench failed: $name@$i" >&2
  done
done
rm -f "$out/.probe.png"
