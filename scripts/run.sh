#!/usr/bin/env bash
# The main job: installs what is missing, builds, and shows the default scene in the GUI.
# Without a display it says so and writes the headless comparison of the default scene
# (every technique: image, error image, metrics JSON) into the folder it names.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
disp="${DISPLAY:-}"
num="${disp#*:}"
num="${num%%.*}"
# A local X display has its socket; a remote one (host:N) is trusted as given.
if [ -n "$disp" ] && { [ -S "/tmp/.X11-unix/X$num" ] || [[ "$disp" != :* ]]; }; then
  exec build/app/shadowlab --scene default "$@"
fi
out="${SHADOWLAB_OUT:-out/default-comparison}"
echo "shadowlab: no display (DISPLAY is '${DISPLAY:-}'): writing the headless comparison of the default scene to $out"
exec build/app/shadowlab-cli compare --scene default --out-dir "$out"
