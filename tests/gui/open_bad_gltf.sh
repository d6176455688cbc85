#!/usr/bin/env bash
# Opening a broken glTF from the GUI — File > Open glTF… with Qt's file dialog, and dropping
# the file on the window (a QDropEvent with its URL), driven by shadowlab-gui-tests --test
# bad-gltf=FILE,FILE,… (see tests/gui/src/GuiTests.cpp) — shows an error dialog and a status
# message naming the file, both elided to a sane length (ui/window/MessageText.h), and the previous
# scene stays loaded and keeps rendering. Every fixture in tests/data that fails to load, a
# generated one whose 40 MB buffer URI the loader's message may echo, and every hostile glTF
# of tests/fixtures/hostile that the CLI refuses.
# usage: open_bad_gltf.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
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

# Every hostile glTF of issue 14 that the CLI refuses (exit 2 in tests/fixtures/hostile/
# expected.tsv): the crafted files as they are, the generated ones (deep nesting, a million-node
# chain, 100,000 cameras, a FIFO, sparse 1 GiB files...) written by gen.py as cli.hostile_fixtures
# does. The FIFOs have no writer: a loader that read them would hang here.
hostile=$here/../fixtures/hostile
python3 "$hostile/gen.py" "$out/gen" >/dev/null
while IFS=$'\t' read -r name status _; do
  [[ $name =~ \.(gltf|glb)$ && $status == 2 ]] || continue
  if [[ $name == gen:* ]]; then f=$out/gen/${name#gen:}; else f=$hostile/$name; fi
  [[ -e "$f" ]] || { echo "FAIL: hostile fixture $f is missing"; exit 1; }
  files+=("$f")
done < <(grep -v '^#' "$hostile/expected.tsv")
(( ${#files[@]} >= 30 )) || { echo "FAIL: only ${#files[@]} files to open"; exit 1; }

list=$(IFS=,; echo "${files[*]}")
rc=0
timeout 600 "$tests" --scene plane-box --technique uniform --test "bad-gltf=$list" \
  >"$out/gui-test.stdout" 2>"$out/gui-test.stderr" || rc=$?
check_bad_files bad-gltf "File > Open" "$out" "$rc" "${files[@]}"
# Passed: do not leave the 40 MB file, the generated fixtures (sparse GiB files, FIFOs) and a
# long stderr behind.
rm -rf "$huge" "$out/gen"
head -c 65536 "$out/gui-test.stderr" >"$out/gui-test.stderr.head" && rm "$out/gui-test.stderr"
echo "PASS"
