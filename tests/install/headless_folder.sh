#!/usr/bin/env bash
# The headless folder that travels (scripts/package-headless.sh): at most 20 MiB, no Qt,
# OpenImageIO or Embree among its libraries, every library it needs (libstdc++ too) resolved
# from the folder, or from the system's C and GL libraries, and a copy outside the build tree renders `diagonal`
# with rtw-backward (timings only: no reference in that build).
#   headless_folder.sh FOLDER OUT_DIR
set -euo pipefail
folder=$1 out=$2/headless_folder
[ -x "$folder/bin/shadowlab-cli" ] ||
  { echo "FAIL: no headless folder at $folder (scripts/package-headless.sh builds it)"; exit 1; }
rm -rf "$out" && mkdir -p "$out"
cp -a "$folder" "$out/copy"
copy="$out/copy"
kib=$(du -sk "$copy" | cut -f1)
echo "headless folder: $kib KiB"
((kib <= 20 * 1024)) || { echo "FAIL: $kib KiB is more than 20 MiB"; exit 1; }
for exe in "$copy"/bin/*; do
  deps=$(ldd "$exe")
  if grep -q "not found" <<<"$deps"; then echo "FAIL: $exe: unresolved: $deps"; exit 1; fi
  if grep -Eiq "libQt|OpenImageIO|embree|libtbb" <<<"$deps"; then
    echo "FAIL: $exe links what the headless folder must not carry:"
    grep -Ei "libQt|OpenImageIO|embree|libtbb" <<<"$deps"
    exit 1
  fi
  # Every non-system library comes from the folder itself.
  while read -r name path; do
    case "$name" in
      linux-vdso* | ld-linux* | libc.* | libm.* | libdl.* | libpthread.* | librt.* | libEGL.* | \
        libGL.* | libGLX.* | libGLdispatch.* | libOpenGL.*) ;;
      *) [[ "$(realpath "$path")" == "$(realpath "$copy")/lib/"* ]] ||
        { echo "FAIL: $exe takes $name from $path, not the folder"; exit 1; } ;;
    esac
  done < <(awk '/=>/ && $3 ~ /^\// {print $1, $3}' <<<"$deps")
done
cd "$out"
version=$(env -u SHADOWLAB_SHADER_DIR -u SHADOWLAB_SCENE_DIR "$copy/bin/shadowlab-cli" version)
echo "$version"
grep -q "^shaders: $(cd "$copy" && pwd -P)/share/shadowlab/shaders$" <<<"$version" ||
  { echo "FAIL: the copy reads shaders from elsewhere"; exit 1; }
grep -q "^reference: this build has no ray-traced reference" <<<"$version" ||
  { echo "FAIL: the folder should be the build without the reference"; exit 1; }
env -u SHADOWLAB_SHADER_DIR -u SHADOWLAB_SCENE_DIR "$copy/bin/shadowlab-cli" render \
  --scene diagonal --technique rtw-backward --size 320x180 --frames 2 --out "$out/diagonal.png" \
  --metrics "$out/diagonal.json" 2>"$out/stderr.txt"
grep -q "no ray-traced reference" "$out/stderr.txt" ||
  { echo "FAIL: no note that the error is not measured"; cat "$out/stderr.txt"; exit 1; }
python3 - "$out/diagonal.json" "$out/diagonal.png" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
assert m["technique"] == "rtw-backward" and m["total_ms"] > 0, m
assert m["error_pct"] is None and m["reference"] is False and m["error_unmeasured"], m
assert [p["name"] for p in m["passes"]], m["passes"]
png = open(sys.argv[2], "rb").read()
assert png[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
assert (w, h) == (320, 180), (w, h)
PY
# The scene generator and the GPU check travel too: the prepared check runs from the copy
# (small sizes), finding its binaries, shaders and scenes in the folder, timings only.
[ -x "$copy/bin/shadowlab-make-scenes" ] || { echo "FAIL: no shadowlab-make-scenes"; exit 1; }
[ -x "$copy/gpu-check.sh" ] || { echo "FAIL: no gpu-check.sh in the folder"; exit 1; }
env -u SHADOWLAB_SHADER_DIR -u SHADOWLAB_SCENE_DIR "$copy/gpu-check.sh" --dry-run \
  --out "$out/gpu-check" >"$out/gpu-check.log" 2>&1 ||
  { echo "FAIL: gpu-check.sh --dry-run from the folder:"; tail -20 "$out/gpu-check.log"; exit 1; }
grep -q "^layout: headless folder\|headless folder" "$out/gpu-check/gpu-check.md" ||
  { echo "FAIL: gpu-check.md does not say it ran from the headless folder"; exit 1; }
grep -q "^| da-rtw |" "$out/gpu-check/gpu-check.md" ||
  { echo "FAIL: gpu-check.md has no da-rtw row"; exit 1; }
echo "PASS: headless folder ($kib KiB) renders diagonal from $copy"
