#!/usr/bin/env bash
# RTW's speed figures, as ratios measured in one run (this machine is noisy):
#  - the share of DA-RTW's rotation estimate (moments, mip chain, PCA, the turn prediction,
#    frustum rotation) in its whole shadow pipeline (every pass except gbuffer, resolve,
#    composite), and DA-RTW's whole overhead over rtw-backward's shadow pipeline (the scatter's
#    counts for the prediction included);
#  - the cost of rtw-backward against uniform at the same resolution (shadow pipeline and
#    whole frame).
# Techniques are interleaved round by round so that machine drift hits all alike.
# Usage: scripts/bench-rtw.sh [SCENE] [RESOLUTION] [ROUNDS]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-default} res=${2:-1024} rounds=${3:-5}
cli=build/app/shadowlab-cli
tmp=$(mktemp -d)
for r in $(seq "$rounds"); do
  for t in uniform rtw-backward da-rtw; do
    "$cli" render --scene "$scene" --technique "$t" --set resolution="$res" --frames 5 \
      --size 1280x720 --out "$tmp/$t.png" --metrics "$tmp/$t.$r.json" >/dev/null
  done
done
python3 - "$tmp" "$rounds" "$scene" "$res" <<'PY'
import json, statistics, sys
tmp, rounds, scene, res = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
camera = {"gbuffer", "resolve", "composite"}
def load(t):
    runs = [json.load(open(f"{tmp}/{t}.{r}.json")) for r in range(1, rounds + 1)]
    shadow = statistics.median(sum(p["ms"] for p in m["passes"] if p["name"] not in camera) for m in runs)
    total = statistics.median(m["total_ms"] for m in runs)
    passes = {p["name"]: statistics.median(next(q["ms"] for q in m["passes"] if q["name"] == p["name"]) for m in runs) for p in runs[0]["passes"]}
    return shadow, total, passes, runs[0]["timing_method"]
u, b, d = load("uniform"), load("rtw-backward"), load("da-rtw")
print(f"scene {scene}, shadow map {res}^2, 1280x720, {rounds} interleaved rounds x 5 frames, timing: {u[3]}")
for name, x in (("uniform", u), ("rtw-backward", b), ("da-rtw", d)):
    print(f"  {name:13s} shadow pipeline {x[0]:8.2f} ms   whole frame {x[1]:8.2f} ms   " +
          ", ".join(f"{k} {v:.2f}" for k, v in x[2].items()))
share = (d[2].get("rotation estimate", 0.0) + d[2].get("moments", 0.0)) / d[0]
print(f"rotation estimate (moments + PCA + turn prediction) share of the da-rtw shadow pipeline: {100*share:.2f} %  (poster: 5.8 %, target < 3 %)")
print(f"  rotation estimate {d[2].get('rotation estimate', 0.0):.2f} ms, moments {d[2].get('moments', 0.0):.2f} ms; importance pass da-rtw {d[2].get('importance', 0.0):.2f} ms, rtw-backward {b[2].get('importance', 0.0):.2f} ms")
print(f"da-rtw over rtw-backward, shadow pipeline: {100*(d[0]/b[0]-1):+.2f} % ({d[0]:.2f} vs {b[0]:.2f} ms)")
print(f"rtw-backward / uniform, shadow pipeline: {b[0]/u[0]:.2f}x   whole frame: {b[1]/u[1]:.2f}x  (seed 002: ~3.5x, target < 2x)")
PY
rm -rf "$tmp"
