#!/usr/bin/env bash
# Presets: every lesson and paper preset (scenes/papers) loads and renders. The bad presets (wrong types, keys, techniques,
# values: exit 2 naming the file and the JSON path) are hostile fixtures,
# tests/fixtures/hostile/preset-*.json, checked by cli.hostile_fixtures.
set -uo pipefail
cli=$1 data=$2 out=$3/preset-input
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
fail=0

# Every lesson is a valid preset.
for f in "$here"/../../scenes/lessons/*.json; do
  if ! err=$(timeout 120 "$cli" render --preset "$f" --size 64x36 --out "$out/lesson.png" 2>&1 >/dev/null); then
    echo "FAIL: lesson $f: $err"; fail=1
  fi
done

# The papers as written (scenes/papers/*.json) render too.
for f in "$here"/../../scenes/papers/*.json; do
  if ! err=$(timeout 120 "$cli" render --preset "$f" --size 64x36 --out "$out/paper.png" 2>&1 >/dev/null); then
    echo "FAIL: paper preset $f: $err"; fail=1
  fi
done

[ $fail -eq 0 ] && echo "ok: every lesson and paper preset loads"
exit $fail
