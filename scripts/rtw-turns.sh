#!/usr/bin/env bash
# DA-RTW's turn against the truth. For each scene and view (every camera bookmark, still, and
# the scene's first path), one interleaved `bench` at 640x360: rtw-backward (the unturned
# frame), DA-RTW with the turn fixed every 15° from -90° to 90° (the true error against the
# angle), DA-RTW at its defaults (rotation.mode=predicted) and with PCA's turn
# (rotation.mode=pca, the poster's rule); and one `render` of the unturned frame that
# publishes the predicted score of every turn (prediction.curve) for both weights (edges,
# pixels). scripts/rtw-turns-table.py turns the CSVs into docs/results/rtw-rotation.md's
# tables and its chart of prediction against truth.
# Usage: scripts/rtw-turns.sh OUTDIR [RESOLUTION] [SCENE[@VIEW]...]
#   VIEW: a camera bookmark's index (still), "path", or "default" (the scene's default view,
#   still); without @VIEW every bookmark and the path (a scene with neither: its default view). SCENE may be a .gltf/.glb file. Default scenes: the built-in directional ones.
#   SHADOWLAB_CLI=path selects another build; FRAMES (default 4) and WARMUP (3) the bench's.
#   PREDICT_ONLY=1 renders the predictions only (the truth's CSVs kept).
#   The turns: every 15° in [-45, 45] (a separable warp of a square map repeats every 90°:
#   measured to the last digit, docs/results/rtw-rotation.md); FULL=1 sweeps [-90, 90].
# The outputs follow the output policy (scripts/lib/output.sh): every file a view may write
# that is a scene file, a folder, a FIFO or a device is refused before the first render
# (exit 2); a log is replaced when its bench ends, never half-written.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/output.sh
out=${1:?usage: scripts/rtw-turns.sh OUTDIR [RESOLUTION] [SCENE[@VIEW]...]}
res=${2:-1024}
shift $(($# >= 2 ? 2 : 1))
cli=${SHADOWLAB_CLI:-build/app/shadowlab-cli}
frames=${FRAMES:-4}
warmup=${WARMUP:-3}
specs=("$@")
[ ${#specs[@]} -gt 0 ] || specs=(band-diagonal band-aligned diagonal corridor default blob
  plane-box thin-pole dueling helmet sunroom figure car
  scenes/third-party/rigged-figure/RiggedFigure.gltf)

# The name of a scene's files, and every file a view of it writes (checked before the work).
scene_name() {
  local name
  name=$(basename "$1")
  echo "${name%.*}"
}
check_view_outputs() {
  local tag w
  tag="$(scene_name "$1")@$2-$res"
  if [ "${PREDICT_ONLY:-0}" != 1 ]; then
    output_check "the CSV" "$out/turns-$tag.csv"
    output_check "the log" "$out/turns-$tag.log"
  fi
  for w in edges pixels; do output_check "the prediction" "$out/prediction-$tag-$w.json"; done
}
output_folder OUTDIR "$out"
for spec in "${specs[@]}"; do output_input "the scene" "${spec%@*}"; done
output_check "the probe image" "$out/.probe.png"
output_check "the prediction image" "$out/.prediction.png"
for spec in "${specs[@]}"; do
  if [[ $spec == *@* ]]; then
    check_view_outputs "${spec%@*}" "${spec#*@}"
  else
    for v in 0 1 2 3 4 5 6 7 path default; do check_view_outputs "$spec" "$v"; done
  fi
done
if [ "${FULL:-0}" = 1 ]; then angles=$(seq -s, -90 15 90); else angles=$(seq -s, -45 15 45); fi

# The views of a scene: every bookmark index that renders, then "path" when it has one; a
# scene with neither (a model as exported) has its default view, "default".
views_of() {
  local scene=$1 i any=0
  for i in 0 1 2 3 4 5 6 7; do
    "$cli" render --scene "$scene" --camera "$i" --technique uniform --size 16x16 --no-reference \
      --out "$out/.probe.png" >/dev/null 2>&1 || break
    echo "$i"
    any=1
  done
  if "$cli" render --scene "$scene" --path 0 --technique uniform --size 16x16 --no-reference \
    --out "$out/.probe.png" >/dev/null 2>&1; then
    echo path
  elif [ $any = 0 ]; then
    echo default
  fi
}

run_view() {
  local scene=$1 view=$2 tag where=() log rc=0
  tag="$(scene_name "$scene")@$view-$res"
  case $view in
    path) where=(--path 0) ;;
    default) where=() ;;
    *) where=(--camera "$view") ;;
  esac
  local f=$frames
  [ "$view" = path ] || f=1  # a still view renders the same frame again
  echo "== $tag" >&2
  if [ "${PREDICT_ONLY:-0}" != 1 ]; then
    output_temp "$out/turns-$tag.log"
    log=$OUTPUT_TEMP
    "$cli" bench --scene "$scene" "${where[@]}" --frames "$f" --warmup "$warmup" --size 640x360 \
      --technique "rtw-backward:resolution=$res" \
      --technique "da-rtw:resolution=$res:rotation.mode=fixed:rotation.fixed_deg=$angles" \
      --technique "da-rtw:resolution=$res" \
      --technique "da-rtw:resolution=$res:rotation.mode=pca" \
      --csv "$out/turns-$tag.csv" >"$log" 2>&1 || rc=$?
    output_commit "$log" "$out/turns-$tag.log"
    if ((rc != 0)); then
      echo "bench failed: $tag (see $out/turns-$tag.log)" >&2
      return 0
    fi
  fi
  local w
  for w in edges pixels; do
    "$cli" render --scene "$scene" "${where[@]}" --technique da-rtw --size 640x360 --frames 2 \
      --set "resolution=$res" --set rotation.mode=fixed --set rotation.fixed_deg=0 \
      --set "prediction.weight=$w" --publish prediction.curve --no-reference \
      --out "$out/.prediction.png" --metrics "$out/prediction-$tag-$w.json" >/dev/null 2>&1 ||
      echo "prediction render failed: $tag $w" >&2
  done
}

for spec in "${specs[@]}"; do
  scene=${spec%@*}
  if [[ $spec == *@* ]]; then
    run_view "$scene" "${spec#*@}"
  else
    for v in $(views_of "$scene"); do run_view "$scene" "$v"; done
  fi
done
rm -f "$out/.probe.png" "$out/.prediction.png"
