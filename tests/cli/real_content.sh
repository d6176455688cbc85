#!/usr/bin/env bash
# The real-content scenes (helmet, sunroom, figure, car: scenes/tools/make_real_content.cpp)
# load as a user's file would, each with its sun, camera bookmarks and a camera path, and
# render (uniform, 160x90, half-way along the path) with a measured error; so does the
# third-party RiggedFigure (scenes/third-party, no light or camera of its own: --light, the
# loader's default view);
# the real-content suite (scenes/suites/real-content.json) passes, its known failures
# reported as such (docs/results/real-content.md).
set -uo pipefail
cli=$1 out=$3/real-content
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
fail=0

for scene in helmet sunroom figure car; do
  if ! "$cli" render --scene "$scene" --technique uniform --set resolution=1024 --size 160x90 \
    --path 0 --path-at 0.5 --out "$out/$scene.png" --metrics "$out/$scene.json" \
    >"$out/$scene.txt" 2>&1; then
    echo "FAIL: render $scene"; cat "$out/$scene.txt"; fail=1; continue
  fi
  python3 - "$out/$scene.json" "$scene" <<'PY' || fail=1
import json, math, sys
m, scene = json.load(open(sys.argv[1])), sys.argv[2]
e = m["error_pct"]
assert e is not None and math.isfinite(e) and 0 <= e < 5, f"{scene}: error_pct {e}"
assert m["covered_pixels"] > 0, f"{scene}: no covered pixel"
print(f"ok: {scene} error {e:.3f} %")
PY
done

rigged=$here/../../scenes/third-party/rigged-figure/RiggedFigure.gltf
if "$cli" render --scene "$rigged" --light 140,40 --technique cascades --size 160x90 \
  --out "$out/rigged.png" --metrics "$out/rigged.json" >"$out/rigged.txt" 2>&1; then
  python3 - "$out/rigged.json" <<'PY' || fail=1
import json, math, sys
m = json.load(open(sys.argv[1]))
e = m["error_pct"]
assert e is not None and math.isfinite(e) and m["covered_pixels"] > 0, f"RiggedFigure: {e}"
# The whole figure is in view and its depth range is small: every stabilised slice covers
# the figure's square (stabilize.scene), not its far wider bounding sphere.
p = m["published"]
assert all(p[f"partition.{i}.scene_clamped"] == 1 for i in range(4)), p
print(f"ok: RiggedFigure error {e:.3f} %, every cascade clamped to the scene")
PY
else
  echo "FAIL: render RiggedFigure"; cat "$out/rigged.txt"; fail=1
fi

"$cli" stability --suite "$here/../../scenes/suites/real-content.json" \
  --json "$out/suite.json" >"$out/suite.txt" 2>"$out/suite.stderr"
rc=$?
if [ $rc -ne 0 ]; then
  echo "FAIL: real-content suite exited $rc"; cat "$out/suite.txt" "$out/suite.stderr"; fail=1
else
  grep "expectations passed" "$out/suite.txt"
  grep -q "2 known failures" "$out/suite.txt" || {
    echo "FAIL: expected the two known failures (sunroom: rtw-backward, rmsm)"; fail=1; }
fi
exit $fail
