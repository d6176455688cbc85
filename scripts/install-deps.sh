#!/usr/bin/env bash
# Installs ShadowLab's build and test dependencies (Debian 12 packages) when missing.
set -euo pipefail
pkgs=(cmake ninja-build g++ pkg-config git
      qt6-base-dev libqt6opengl6-dev qt6-charts-dev qt6-qpa-plugins libglm-dev
      libtinygltf-dev nlohmann-json3-dev libstb-dev libopenimageio-dev
      libepoxy-dev libegl-dev libegl-mesa0 libgl1-mesa-dri libgl-dev
      libembree-dev libgtest-dev xvfb xauth python3 ccache
      clang libclang-rt-14-dev)  # scripts/fuzz.sh: clang and libFuzzer (libclang_rt.fuzzer)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "shadowlab: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
