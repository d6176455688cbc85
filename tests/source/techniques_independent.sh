#!/usr/bin/env bash
# Techniques never include each other: a file under renderer/techniques/X/ includes only its
# own folder ("Name.h" or "techniques/X/..."), core/, algo/, gl/, scene/, metrics/ and common/
# (shaders/common, shared with GLSL). What two techniques share lives in renderer/core (GL) or
# renderer/algo (plain C++). Both forms of a cross include are caught: "techniques/Y/..." and a
# relative "../Y/...".
# usage: techniques_independent.sh <repository root>
set -euo pipefail
root=$1
dir=$root/renderer/techniques
mapfile -t folders < <(find "$dir" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | sort)
if (( ${#folders[@]} < 5 )); then
  echo "FAIL: found only ${#folders[@]} technique folders in $dir"
  exit 1
fi
fail=0
checked=0
for x in "${folders[@]}"; do
  while IFS= read -r -d '' file; do
    rel=${file#"$root"/}
    lineno=0
    while IFS= read -r line; do
      lineno=$((lineno + 1))
      [[ $line =~ ^[[:space:]]*#[[:space:]]*include[[:space:]]*\"([^\"]*)\" ]] || continue
      inc=${BASH_REMATCH[1]}
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
          if [[ ! -f $(dirname "$file")/$inc ]]; then
            echo "FAIL: $rel:$lineno includes \"$inc\", which is not in its own folder"
            fail=1
          fi ;;
      esac
    done <"$file"
  done < <(find "$dir/$x" -type f \( -name '*.h' -o -name '*.cpp' \) -print0)
done
# The search itself works: the techniques do include core/ and their own headers.
if (( checked < 50 )); then
  echo "FAIL: only $checked includes found under $dir (is the search broken?)"
  fail=1
fi
(( fail == 0 )) && echo "PASS: $checked includes in ${#folders[@]} technique folders, none of another technique"
exit $fail
