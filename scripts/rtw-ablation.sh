#!/usr/bin/env bash
# DA-RTW against the poster, one deviation at a time: one interleaved `bench` per scene with
# rtw-backward (also on the rotation-invariant frustum: the poster's area without a rotation),
# da-rtw at its defaults (rotation.mode=predicted), the poster's rule gated as the tool once
# defaulted to (rotation.mode=pca, pca.min_anisotropy=0.9, pca.min_spread=0.05), the rule
# turning whatever the importance ("gate off": rotation.mode=pca, metric in metres, both gates
# 0), "gate off" with each switch alone set to the poster's choice (and with each of the two
# gates alone), and the poster
# (scenes/papers/000-da-rtw.json), at 512/1024/2048, 640x360, 4 frames along the scene's path.
# Usage: scripts/rtw-ablation.sh OUTDIR [SCENE...]   (default: the directional scenes)
# Writes OUTDIR/ablation-SCENE.csv and .png (error against time), and OUTDIR/ablation.md: the
# tables of docs/results/rtw-ablation.md. The outputs follow the output policy
# (scripts/lib/output.sh): one that is a scene file, a folder, a FIFO or a device is refused
# before the first bench (exit 2), and ablation.md is replaced only when every table was made.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/output.sh
out=${1:?usage: scripts/rtw-ablation.sh OUTDIR [SCENE...]}
shift
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(diagonal corridor default band-diagonal band-aligned blob
  plane-box thin-pole dueling)
cli=${SHADOWLAB_CLI:-build/app/shadowlab-cli}  # another build: SHADOWLAB_CLI=path
res=resolution=512,1024,2048
gateoff="$res:rotation.mode=pca:pca.metric=metres:pca.min_anisotropy=0:pca.min_spread=0"
gated="$res:rotation.mode=pca:pca.min_anisotropy=0.9:pca.min_spread=0.05"
poster="$res:rotation.mode=pca:importance.stride=1:importance.orientation=0:pca.source=im"
poster+=":pca.metric=im-units"
poster+=":light.fit=rotation-invariant:pca.threshold=0.9999:pca.min_anisotropy=0:pca.min_spread=0"
output_folder OUTDIR "$out"
for s in "${scenes[@]}"; do output_input "the scene" "$s"; done
for s in "${scenes[@]}"; do
  output_check "the CSV" "$out/ablation-$s.csv"
  output_check "the chart" "$out/ablation-$s.png"
done
output_check "the tables" "$out/ablation.md"
for s in "${scenes[@]}"; do
  "$cli" bench --scene "$s" --frames 4 --warmup 1 --size 640x360 \
    --technique "rtw-backward:$res" \
    --technique "rtw-backward:$res:light.fit=rotation-invariant" \
    --technique "da-rtw:$res" \
    --technique "da-rtw:$gated" \
    --technique "da-rtw:$gateoff" \
    --technique "da-rtw:$gateoff:pca.source=im" \
    --technique "da-rtw:$gateoff:pca.metric=im-units" \
    --technique "da-rtw:$gateoff:light.fit=rotation-invariant" \
    --technique "da-rtw:$gateoff:importance.stride=1" \
    --technique "da-rtw:$gateoff:importance.orientation=0" \
    --technique "da-rtw:$gateoff:pca.min_anisotropy=0.9" \
    --technique "da-rtw:$gateoff:pca.min_spread=0.05" \
    --technique "da-rtw:$poster" \
    --csv "$out/ablation-$s.csv" --chart "$out/ablation-$s.png" --chart-y log
done
python3 scripts/rtw-ablation-table.py "$out" "${scenes[@]}" --out "$out/ablation.md"
