#!/usr/bin/env bash
# A scene file whose name is not UTF-8: the metrics JSON is written (the name's bad bytes as
# U+FFFD), not lost after the PNG with a JSON library message naming no file.
set -uo pipefail
cli=$1 out=$3/non-utf8-names
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out"
fail=0
check() {  # check DESCRIPTION COMMAND...: passes when the command succeeds
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}
scene=$out/$'caf\xe9'.gltf
cp "$here/../../scenes/plane-box.gltf" "$scene"
"$cli" render --scene "$scene" --technique uniform --size 64x36 --out "$out/r.png" \
  --metrics "$out/r.json" >/dev/null 2>"$out/render.stderr"
rc=$?
check "render exits 0 ($(cat "$out/render.stderr"))" test $rc -eq 0
check "the metrics are valid JSON naming the scene" python3 -c '
import json, sys
j = json.load(open(sys.argv[1], encoding="utf-8"))
assert j["scene"] == "caf\ufffd", j["scene"]
' "$out/r.json"
"$cli" stability --scene "$scene" --technique uniform --frames 2 --size 64x36 \
  --json "$out/s.json" >/dev/null 2>"$out/stability.stderr"
rc=$?
check "stability exits 0 ($(grep -v '^stability:' "$out/stability.stderr"))" test $rc -eq 0
exit $fail
