#!/usr/bin/env bash
# Outputs never overwrite inputs: a preset, the files a scene loaded (its buffer), compare's
# generated names (summary.json, <configuration>.png) and its montage are checked before any
# work, after resolving symbolic links (exit 2, the input untouched); the same configuration
# listed twice gets its own files; a buffer that a symbolic link leads outside the scene's
# folder is refused.
set -uo pipefail
cli=$1 out=$3/protected-inputs
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out" && mkdir -p "$out/scene" "$out/cmp"
fail=0
check() {  # check DESCRIPTION COMMAND...: passes when the command succeeds
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}
refused() {  # refused DESCRIPTION PATTERN COMMAND...: exit 2 with PATTERN on stderr
  local what=$1 pattern=$2; shift 2
  "$@" >/dev/null 2>"$out/stderr"
  local rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$pattern" "$out/stderr"; then echo "ok: $what"
  else echo "FAIL: $what (exit $rc: $(cat "$out/stderr"))"; fail=1; fi
}
# plane-box with its buffer in scene.bin next to it.
python3 - "$here/../../scenes/plane-box.gltf" "$out/scene" <<'PY'
import base64, json, sys
g = json.load(open(sys.argv[1]))
raw = base64.b64decode(g["buffers"][0]["uri"].split(",", 1)[1])
open(sys.argv[2] + "/scene.bin", "wb").write(raw)
g["buffers"][0]["uri"] = "scene.bin"
json.dump(g, open(sys.argv[2] + "/scene.gltf", "w"))
PY
cp "$out/scene/scene.bin" "$out/scene.bin.orig"
scene=$out/scene/scene.gltf
common=(--technique uniform --size 64x36)

refused "render: --metrics onto the scene's buffer" "which the scene scene loaded" \
  "$cli" render --scene "$scene" "${common[@]}" --out "$out/r.png" --metrics "$out/scene/scene.bin"
check "the buffer is untouched" cmp -s "$out/scene/scene.bin" "$out/scene.bin.orig"
ln -s scene/scene.bin "$out/link.json"
refused "render: --metrics through a symbolic link to the buffer" "which the scene scene loaded" \
  "$cli" render --scene "$scene" "${common[@]}" --out "$out/r.png" --metrics "$out/link.json"
check "the buffer is untouched (link)" cmp -s "$out/scene/scene.bin" "$out/scene.bin.orig"
echo '{"scene": "plane-box", "technique": "uniform"}' >"$out/preset.json"
refused "render: --metrics onto the --preset" "is the same file as --preset" \
  "$cli" render --preset "$out/preset.json" --size 64x36 --out "$out/r.png" --metrics "$out/preset.json"
cp "$out/preset.json" "$out/cmp/summary.json"
refused "compare: summary.json is the --preset" "is the same file as --preset" \
  "$cli" compare --preset "$out/cmp/summary.json" --size 64x36 --technique uniform --out-dir "$out/cmp"
refused "compare: --montage onto a configuration's image" "--montage: .* is the same file as --out-dir (uniform)" \
  "$cli" compare --scene plane-box "${common[@]}" --out-dir "$out/cmp" --montage "$out/cmp/uniform.png"
refused "bench: --csv onto the scene's buffer" "which the scene scene loaded" \
  "$cli" bench --scene "$scene" --technique uniform --frames 1 --csv "$out/scene/scene.bin"
check "the buffer is untouched (bench)" cmp -s "$out/scene/scene.bin" "$out/scene.bin.orig"

# The same configuration twice: two sets of files.
"$cli" compare --scene plane-box --technique uniform --technique uniform --size 64x36 \
  --out-dir "$out/twice" >/dev/null 2>&1
check "compare twice: exit 0" test $? -eq 0
check "compare twice: two images" test -e "$out/twice/uniform.png" -a -e "$out/twice/uniform__2.png"

# A buffer that a symbolic link leads outside the scene's folder.
mkdir -p "$out/linked"
cp "$scene" "$out/linked/scene.gltf"
ln -s ../scene.bin.orig "$out/linked/scene.bin"
refused "a buffer linked outside the scene's folder" "leads outside the scene's folder" \
  "$cli" render --scene "$out/linked/scene.gltf" "${common[@]}" --out "$out/linked.png"
exit $fail
