#!/usr/bin/env bash
# Every lesson's claims, window, live numbers and labels (lesson_claims.sh) on a 1280x800
# screen: a lecture hall's projector is often that small.
# usage: lesson_claims_1280x800.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
LESSON_SCREEN=1280x800 exec bash "$(cd "$(dirname "$0")" && pwd)/lesson_claims.sh" "$@"
