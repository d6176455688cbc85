#!/usr/bin/env bash
# Configures and builds ShadowLab into build/ (CMake preset "default", Ninja, warnings are errors).
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache (CMakeLists.txt uses it when present): paths relative to the checkout, so another
# clone of the repository (CI) reuses the cache.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset default >/dev/null
cmake --build --preset default
