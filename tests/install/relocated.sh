#!/usr/bin/env bash
# `cmake --install` into a prefix, the prefix moved elsewhere: the programs find their shaders
# and scenes beside themselves (share/shadowlab), not in the source tree they were built from,
# and shadowlab-cli renders `default` from there.
#   relocated.sh BUILD_DIR OUT_DIR
set -euo pipefail
build=$1 out=$2/relocated
rm -rf "$out" && mkdir -p "$out"
cmake --install "$build" --prefix "$out/first" >/dev/null
mv "$out/first" "$out/moved"
prefix="$out/moved"
cli="$prefix/bin/shadowlab-cli"
[ -x "$cli" ] || { echo "FAIL: $cli not installed"; exit 1; }
for f in share/shadowlab/shaders/common share/shadowlab/scenes/default.gltf \
         share/shadowlab/scenes/lessons; do
  [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
done
if [ -x "$build/app/shadowlab" ]; then
  for f in bin/shadowlab share/applications/shadowlab.desktop \
           share/icons/hicolor/scalable/apps/shadowlab.svg; do
    [ -e "$prefix/$f" ] || { echo "FAIL: $f not installed"; exit 1; }
  done
fi
# Development overrides off: what an installed program does on a user's machine.
version=$(env -u SHADOWLAB_SHADER_DIR -u SHADOWLAB_SCENE_DIR "$cli" version)
echo "$version"
real=$(cd "$prefix" && pwd -P)
grep -qx "shaders: $real/share/shadowlab/shaders" <<<"$version" ||
  { echo "FAIL: the moved tree reads shaders from elsewhere"; exit 1; }
grep -qx "scenes: $real/share/shadowlab/scenes" <<<"$version" ||
  { echo "FAIL: the moved tree reads scenes from elsewhere"; exit 1; }
# Rendering from a folder that is not the source tree, with only the moved tree's data.
cd "$out"
env -u SHADOWLAB_SHADER_DIR -u SHADOWLAB_SCENE_DIR "$cli" render --scene default \
  --technique uniform --size 160x90 --out "$out/default.png" --metrics "$out/default.json" >/dev/null
python3 - "$out/default.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
assert m["covered_pixels"] > 0 and m["error_pct"] is not None, m
PY
# The development override still wins (shader hot-reload from a source tree).
src=$(SHADOWLAB_SHADER_DIR=/nonexistent/shaders "$cli" version | sed -n 's/^shaders: //p')
[ "$src" = /nonexistent/shaders ] || { echo "FAIL: SHADOWLAB_SHADER_DIR ignored ($src)"; exit 1; }
echo "PASS: installed tree moved to $prefix renders default"
