#!/usr/bin/env bash
# Installs what is missing, builds (the preset, a plain Release build, the headless folder),
# and runs every test (ctest), then fuzzes the file readers for 60 s per target
# (scripts/fuzz.sh). GUI tests start their own Xvfb. CI (.ci/run) calls exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
# A user's plain Release build (no preset: -O3, no -Werror), everything it builds (the tests
# too, not run), must compile; its own folder, incremental after the first run.
cmake -S . -B build-release -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1 cmake --build build-release -j2
# The headless folder that travels (no Qt, OpenImageIO or Embree; build-headless/), built
# here so that ctest's install.headless_package only checks it is up to date.
scripts/package-headless.sh >/dev/null
ctest --preset default -j2 "$@"
# A short fuzzing run of the file readers: 60 s per target, after the tests
# (SHADOWLAB_FUZZ_SECONDS=0: build the fuzz targets only).
scripts/fuzz.sh "${SHADOWLAB_FUZZ_SECONDS:-60}"
