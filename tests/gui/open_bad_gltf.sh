#!/usr/bin/env bash
# Opening a broken glTF from the GUI — File > Open glTF… with Qt's file dialog, and dropping
# the file on the window (a QDropEvent with its URL), driven by shadowlab --self-test
# bad-gltf=FILE,FILE,… (see ui/MainWindowSelfTest.cpp) — shows an error dialog and a status
# message naming the file, both elided to a sane length (ui/MessageText.h), and the previous
# scene stays loaded and keeps rendering. Every fixture in tests/data that fails to load, plus
# a generated one whose 40 MB buffer URI the loader's message may echo.
# usage: open_bad_gltf.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
data=$2
out=$3/open_bad_gltf
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
source "$here/bad_files.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

# The fixtures that must fail to load (tests/cpu/GltfLoaderTest.cpp checks their messages).
broken=(malformed.gltf truncated.glb draco-required.gltf bad-index.gltf
  buffer-out-of-range.gltf nan-position.gltf no-triangles.gltf)
files=()
for f in "${broken[@]}"; do
  [[ -f "$data/$f" ]] || { echo "FAIL: fixture $data/$f is missing"; exit 1; }
  files+=("$data/$f")
done

# A buffer whose URI is 40 MB long (a missing file).
huge=$out/huge-uri.gltf
{
  printf '{"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"'
  head -c 40000000 /dev/zero | tr '\0' a
  printf '.bin"}],"bufferViews":[{"buffer":0,"byteLength":36}],'
  printf '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",'
  printf '"min":[0,0,0],"max":[1,1,0]}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],'
  printf '"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0}\n'
} >"$huge"
files+=("$huge")

list=$(IFS=,; echo "${files[*]}")
rc=0
timeout 120 "$app" --scene plane-box --technique uniform --self-test "bad-gltf=$list" \
  >"$out/self-test.stdout" 2>"$out/self-test.stderr" || rc=$?
check_bad_files bad-gltf "File > Open" "$out" "$rc" "${files[@]}"
# Passed: do not leave the 40 MB file (and a long stderr) behind.
rm -f "$huge"
head -c 65536 "$out/self-test.stderr" >"$out/self-test.stderr.head" && rm "$out/self-test.stderr"
echo "PASS"
