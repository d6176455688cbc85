#!/usr/bin/env bash
# DA-RTW against the poster, one deviation at a time: one interleaved `bench` per scene with
# rtw-backward, da-rtw at its defaults, da-rtw with each switch alone set to the poster's
# choice, the poster (scenes/papers/000-da-rtw.json), and rtw-backward on the rotation-
# invariant frustum (the same area as the poster's, without the rotation), at 512/1024/2048.
# Usage: scripts/rtw-ablation.sh OUTDIR [SCENE...]   (default: the directional scenes)
# Writes OUTDIR/ablation-SCENE.csv and .png (error against time).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: scripts/rtw-ablation.sh OUTDIR [SCENE...]}
shift
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(diagonal corridor default plane-box thin-pole dueling)
cli=build/app/shadowlab-cli
res=resolution=512,1024,2048
poster="importance.stride=1:importance.orientation=0:pca.source=im:pca.metric=im-units"
poster+=":light.fit=rotation-invariant:pca.threshold=0.9999"
mkdir -p "$out"
for s in "${scenes[@]}"; do
  "$cli" bench --scene "$s" --frames 4 --warmup 1 --size 640x360 \
    --technique "rtw-backward:$res" \
    --technique "rtw-backward:$res:light.fit=rotation-invariant" \
    --technique "da-rtw:$res" \
    --technique "da-rtw:$res:pca.source=im" \
    --technique "da-rtw:$res:pca.metric=im-units" \
    --technique "da-rtw:$res:light.fit=rotation-invariant" \
    --technique "da-rtw:$res:importance.stride=1" \
    --technique "da-rtw:$res:importance.orientation=0" \
    --technique "da-rtw:$res:$poster" \
    --csv "$out/ablation-$s.csv" --chart "$out/ablation-$s.png" --chart-y log
done
