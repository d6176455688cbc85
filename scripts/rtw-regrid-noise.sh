#!/usr/bin/env bash
# How much a turn changes the error by itself: DA-RTW with the turn fixed at 0, 1, 2, 3 and
# 4 degrees, one frame of each still view (every camera bookmark) at 640x360. Turns that
# small change no texel's size (the frustum's area by < 1 %), only where every shadow edge
# falls against the texel grid; the spread of their errors is what any turn's error carries on
# top of what it gains. scripts/rtw-regrid-noise.py summarises it (docs/results/rtw-rotation.md).
# Usage: scripts/rtw-regrid-noise.sh OUTDIR [RESOLUTION] [SCENE...]
# The outputs follow the output policy (scripts/lib/output.sh): a CSV or log that is a scene
# file, a folder, a FIFO or a device is refused before the first render (exit 2); a log is
# replaced when its bench ends, never half-written.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/output.sh
out=${1:?usage: scripts/rtw-regrid-noise.sh OUTDIR [RESOLUTION] [SCENE...]}
res=${2:-1024}
shift $(($# >= 2 ? 2 : 1))
cli=${SHADOWLAB_CLI:-build/app/shadowlab-cli}
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(band-aligned diagonal corridor default blob plane-box thin-pole
  dueling helmet sunroom figure car)
output_folder OUTDIR "$out"
for scene in "${scenes[@]}"; do output_input "the scene" "$scene"; done
output_check "the probe image" "$out/.probe.png"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene")
  for i in 0 1 2 3 4 5 6 7; do
    output_check "the CSV" "$out/regrid-${name%.*}@$i-$res.csv"
    output_check "the log" "$out/regrid-${name%.*}@$i-$res.log"
  done
done
for scene in "${scenes[@]}"; do
  name=$(basename "$scene")
  name=${name%.*}
  for i in 0 1 2 3 4 5 6 7; do
    "$cli" render --scene "$scene" --camera "$i" --technique uniform --size 16x16 --no-reference \
      --out "$out/.probe.png" >/dev/null 2>&1 || break
    echo "== $name@$i" >&2
    output_temp "$out/regrid-$name@$i-$res.log"
    rc=0
    "$cli" bench --scene "$scene" --camera "$i" --frames 1 --warmup 1 --size 640x360 \
      --technique "da-rtw:resolution=$res:rotation.mode=fixed:rotation.fixed_deg=0,1,2,3,4" \
      --csv "$out/regrid-$name@$i-$res.csv" >"$OUTPUT_TEMP" 2>&1 || rc=$?
    output_commit "$OUTPUT_TEMP" "$out/regrid-$name@$i-$res.log"
    ((rc == 0)) || echo "bench failed: $name@$i" >&2
  done
done
rm -f "$out/.probe.png"
