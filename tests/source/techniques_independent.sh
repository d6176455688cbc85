#!/usr/bin/env bash
# Techniques never include each other: a file under renderer/techniques/X/ includes only its
# own folder ("Name.h" or "techniques/X/..."), core/, algo/, gl/, scene/, metrics/ and common/
# (shaders/common, shared with GLSL). What two techniques share lives in renderer/core (GL) or
# renderer/algo (plain C++). Both forms of a cross include are caught: "techniques/Y/..." and a
# relative "../Y/...".
# The same holds for their shaders: a file under shaders/X/ includes only shaders/common/ and
# its own folder (shaders/common/ only common/ and the technique's "@lookup" alias); a file of
# renderer/techniques/X/ loads no shader of another technique's folder, and renderer/core/
# none of any technique's folder. What two techniques' shaders share lives in shaders/common/
# (by family: common/paged/, common/tiled/).
# usage: techniques_independent.sh <repository root>
set -euo pipefail
root=$1
dir=$root/renderer/techniques
shaders=$root/shaders
mapfile -t folders < <(find "$dir" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort)
if (( ${#folders[@]} < 5 )); then
  echo "FAIL: found only ${#folders[@]} technique folders in $dir"
  exit 1
fi
fail=0

# Runs CHECK <folder> <file relative to root> <line> <included name> for each
# `#include "NAME"` (C++ or GLSL) of the files under BASE/<folder>/ matched by the find test.
forEachInclude() {  # <CHECK> <BASE> <find name test...>; the folders come from $scanFolders
  local check=$1 base=$2 x file lineno inc
  shift 2
  for x in "${scanFolders[@]}"; do
    while IFS= read -r -d '' file; do
      while IFS=$'\t' read -r lineno inc; do
        "$check" "$x" "${file#"$root"/}" "$lineno" "$inc"
      done < <(awk 'match($0, /^[[:space:]]*#[[:space:]]*include[[:space:]]*"[^"]*"/) {
                      s = substr($0, RSTART, RLENGTH); sub(/^[^"]*"/, "", s); sub(/"$/, "", s)
                      print FNR "\t" s
                    }' "$file")
    done < <(find "$base/$x" -type f \( "$@" \) -print0)
  done
}

# C++ includes of renderer/techniques/X/.
checked=0
# shellcheck disable=SC2317  # called through forEachInclude
checkTechniqueInclude() {  # <X> <file> <line> <included>
  local x=$1 rel=$2 lineno=$3 inc=$4
  checked=$((checked + 1))
  case $inc in
    techniques/"$x"/*) ;;                                  # its own folder
    techniques/*)
      echo "FAIL: $rel:$lineno includes \"$inc\" (another technique's folder)"
      fail=1 ;;
    ../*)
      echo "FAIL: $rel:$lineno includes \"$inc\" (a relative path out of its folder)"
      fail=1 ;;
    core/* | algo/* | gl/* | scene/* | metrics/* | common/*) ;;
    */*)
      echo "FAIL: $rel:$lineno includes \"$inc\" (only core/, algo/, gl/, scene/, metrics/, common/ and its own folder)"
      fail=1 ;;
    *)
      if [[ ! -f $(dirname "$root/$rel")/$inc ]]; then
        echo "FAIL: $rel:$lineno includes \"$inc\", which is not in its own folder"
        fail=1
      fi ;;
  esac
}
scanFolders=("${folders[@]}")
forEachInclude checkTechniqueInclude "$dir" -name '*.h' -o -name '*.cpp'
# The search itself works: the techniques do include core/ and their own headers.
if (( checked < 50 )); then
  echo "FAIL: only $checked includes found under $dir (is the search broken?)"
  fail=1
fi

# Shader includes: shaders/X/ -> X/ or common/; shaders/common/ -> common/ or an "@" alias.
shaderIncludes=0
# shellcheck disable=SC2317  # called through forEachInclude
checkShaderInclude() {  # <X> <file> <line> <included>
  local x=$1 rel=$2 lineno=$3 inc=$4
  shaderIncludes=$((shaderIncludes + 1))
  case $inc in
    common/* | "$x"/*) ;;
    @*)
      if [[ $x != common ]]; then
        echo "FAIL: $rel:$lineno includes the alias \"$inc\" (only shaders/common/ may)"
        fail=1
      fi ;;
    *)
      echo "FAIL: $rel:$lineno includes \"$inc\" (a shader includes only common/ and its own folder $x/)"
      fail=1 ;;
  esac
}
mapfile -t scanFolders < <(find "$shaders" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort)
forEachInclude checkShaderInclude "$shaders" -name '*'
if (( shaderIncludes < 20 )); then
  echo "FAIL: only $shaderIncludes includes found under $shaders (is the search broken?)"
  fail=1
fi

# Shader paths named in C++ strings ("FOLDER/FILE.EXT", FOLDER one of shaders/): renderer/core/
# names only common/ ones, renderer/techniques/X/ only common/ and X/ ones.
shaderPaths=0
checkShaderPaths() {  # <own folder besides common/, "" for core> <files...>
  local own=$1 file rel lineno path folder
  shift
  for file in "$@"; do
    rel=${file#"$root"/}
    while IFS=: read -r lineno path; do
      path=${path//\"/}
      folder=${path%%/*}
      [[ -d $shaders/$folder ]] || continue
      shaderPaths=$((shaderPaths + 1))
      [[ $folder == common || $folder == "$own" ]] && continue
      if [[ -z $own ]]; then
        echo "FAIL: $rel:$lineno names the shader \"$path\" (core loads shaders from common/ only)"
      else
        echo "FAIL: $rel:$lineno names the shader \"$path\" (another technique's folder)"
      fi
      fail=1
    done < <(grep -noE '"[A-Za-z0-9_-]+/[^"]*\.(glsl|comp|vert|frag|geom|tesc|tese)"' "$file" || true)
  done
}
mapfile -t files < <(find "$root/renderer/core" -type f \( -name '*.h' -o -name '*.cpp' \) | sort)
checkShaderPaths "" "${files[@]}"
for x in "${folders[@]}"; do
  mapfile -t files < <(find "$dir/$x" -type f \( -name '*.h' -o -name '*.cpp' \) | sort)
  checkShaderPaths "$x" "${files[@]}"
done
if (( shaderPaths < 20 )); then
  echo "FAIL: only $shaderPaths shader paths found in renderer/core and renderer/techniques (is the search broken?)"
  fail=1
fi

if (( fail == 0 )); then
  echo "PASS: $checked includes in ${#folders[@]} technique folders, none of another technique;" \
    "$shaderIncludes shader includes and $shaderPaths shader paths in C++, none of another folder"
fi
exit $fail
