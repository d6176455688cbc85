#!/usr/bin/env bash
# Builds the headless folder that travels: shadowlab-cli without Qt, OpenImageIO or Embree
# (PNG through stb; no ray-traced reference: timings only), with the scene generator, the
# shaders, the scenes and scripts/gpu-check.sh, and the non-system libraries it needs beside
# it ($ORIGIN/../lib, libstdc++ included). The GL driver (libEGL, libGL) is the target's.
#
#   scripts/package-headless.sh [--build DIR (build-headless)] [--out FOLDER (DIR/shadowlab-headless)]
#
# FOLDER is replaced whole: an existing FOLDER that is not an earlier headless folder (no
# bin/shadowlab-cli), or one that holds the source tree or --build, is refused before the
# build (exit 2), never deleted.
#
# Copy FOLDER to a Linux machine with an OpenGL 4.5 EGL driver and run
#   FOLDER/bin/shadowlab-cli render --scene diagonal --technique rtw-backward --out x.png
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"
build="build-headless"
out=""
while (($#)); do
  case "$1" in
    --build) build="${2:?--build: missing folder}"; shift 2 ;;
    --out) out="${2:?--out: missing folder}"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) echo "package-headless.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ -n "$out" ] || out="$build/shadowlab-headless"
# FOLDER is removed before the new one moves in: never a folder of other files, the sources
# or the build.
refuse() {
  echo "package-headless.sh: --out '$out' $1 (refused: it would be deleted)" >&2
  exit 2
}
resolved=$(realpath -m -- "$out")
for kept in "$src" "$(realpath -m -- "$build")"; do
  [[ $kept/ != "${resolved%/}"/* ]] || refuse "holds '$kept'"
done
if [[ -e $resolved && ! -d $resolved ]]; then
  refuse "is not a folder"
elif [[ -d $resolved && ! -x $resolved/bin/shadowlab-cli && -n $(ls -A "$resolved") ]]; then
  refuse "is a folder of other files (no bin/shadowlab-cli)"
fi
export CCACHE_BASEDIR="$src" CCACHE_NOHASHDIR=1
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DSHADOWLAB_GUI=OFF \
  -DSHADOWLAB_REFERENCE=OFF -DSHADOWLAB_OIIO=OFF -DSHADOWLAB_BUILD_TESTS=OFF \
  -DSHADOWLAB_PORTABLE=ON >/dev/null
cmake --build "$build" --target shadowlab-cli shadowlab-make-scenes -j"$(nproc)"

stage="$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-headless.XXXXXX")"
trap 'rm -rf "$stage"' EXIT
cmake --install "$build" --prefix "$stage" --strip >/dev/null
[ -f scripts/gpu-check.sh ] && install -m 755 scripts/gpu-check.sh "$stage/gpu-check.sh"

# Non-system libraries beside the programs, libstdc++ and libgcc_s included (a target with an
# older GCC runtime still runs them). Not copied: the C library family (the target has its
# own) and the GL/EGL dispatch libraries (the target's driver provides them).
mkdir -p "$stage/lib"
system='^(linux-vdso|ld-linux|libc|libm|libdl|libpthread|librt|libEGL|libGL|libGLX|libGLdispatch|libOpenGL)\.'
for exe in "$stage"/bin/*; do
  ldd "$exe" | awk '/=>/ && $3 ~ /^\// {print $1, $3}'
done | sort -u | while read -r name path; do
  [[ "$name" =~ $system ]] && continue
  cp -L "$path" "$stage/lib/$name"
  strip --strip-unneeded "$stage/lib/$name" 2>/dev/null || true
done
# A copied library's own dependencies, one level (libtinygltf -> libstb).
for lib in "$stage"/lib/*; do
  ldd "$lib" | awk '/=>/ && $3 ~ /^\// {print $1, $3}'
done | sort -u | while read -r name path; do
  [[ "$name" =~ $system ]] && continue
  [ -e "$stage/lib/$name" ] || cp -L "$path" "$stage/lib/$name"
done

rm -rf "$out"
mkdir -p "$(dirname "$out")"
mv "$stage" "$out"
trap - EXIT
chmod 755 "$out"
echo "headless folder: $out ($(du -sh "$out" | cut -f1))"
