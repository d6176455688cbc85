#!/usr/bin/env bash
# app/ holds the programs, not the GUI's parts: shadowlab-cli measures with shadowlab_measure
# (renderer/measure/) and draws with shadowlab_figures (renderer/figures/), so no file in app/
# includes a ui/ header and app's CMake puts no ui/ folder on an include path. The one
# exception is the GUI program's entry point: app/gui/main.cpp calls shadowlab_ui's runGui
# (launch/Launch.h), which is what that program is.
# usage: app_includes_no_ui.sh <repository root>
set -euo pipefail
root=$1
fail=0
while IFS= read -r file; do
  rel=${file#"$root"/}
  dir=$(dirname "$file")
  while IFS= read -r line; do
    inc=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"([^"]+)".*/\1/' <<<"$line")
    [[ $rel == app/gui/main.cpp && $inc == launch/Launch.h ]] && continue
    # A ui/ header: named through ui/ (or ../ui/), or found only under ui/ (not beside the
    # file, not in the renderer's libraries).
    if [[ $inc == ui/* || $inc == */ui/* ]] ||
       { [[ -e $root/ui/$inc ]] && [[ ! -e $dir/$inc ]] && [[ ! -e $root/renderer/$inc ]]; }; then
      echo "FAIL: $rel includes the ui/ header \"$inc\""
      fail=1
    fi
  done < <(grep -E '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$file" || true)
done < <(find "$root/app" -type f \( -name '*.cpp' -o -name '*.h' \) | sort)
# No include path into ui/ in app's CMake files (CMAKE_SOURCE_DIR, PROJECT_SOURCE_DIR, ../ui).
while IFS= read -r hit; do
  echo "FAIL: app CMake adds ui/ to an include path: ${hit#"$root"/}"
  fail=1
done < <(find "$root/app" -name CMakeLists.txt -o -name '*.cmake' | xargs grep -nHE \
           'include_directories.*(SOURCE_DIR\}|\.\.)/ui\b|INCLUDE_DIRECTORIES.*/ui\b' || true)
if (( fail )); then exit 1; fi
echo "app/: no ui/ header included, no ui/ include path"
