#!/usr/bin/env bash
# Configures and builds ShadowLab into build/ (CMake preset "default", Ninja, warnings are errors).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default
