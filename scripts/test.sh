#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test (ctest). GUI tests start their own
# Xvfb. CI (.ci/run) calls exactly this.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --preset default -j2 "$@"
