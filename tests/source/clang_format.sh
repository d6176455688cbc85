#!/usr/bin/env bash
# Every tracked C++ source is formatted by the repository's .clang-format (clang-format
# --dry-run --Werror): `clang-format -i FILE` fixes one.
# usage: clang_format.sh <repository root>
set -euo pipefail
root=$1
cd "$root"
command -v clang-format >/dev/null || { echo "FAIL: clang-format is not installed"; exit 1; }
mapfile -t files < <(git ls-files '*.cpp' '*.h' 2>/dev/null || true)
if ((${#files[@]} == 0)); then  # not a git checkout (a source tarball): every source file
  mapfile -t files < <(find app renderer shaders ui scenes tests -name '*.cpp' -o -name '*.h')
fi
((${#files[@]} > 100)) || { echo "FAIL: only ${#files[@]} C++ files found under $root"; exit 1; }
if ! out=$(clang-format --dry-run --Werror "${files[@]}" 2>&1); then
  echo "FAIL: not formatted (clang-format -i FILE):"
  grep -oE '^[^:]+\.(cpp|h):' <<<"$out" | sort -u | sed 's/:$//; s/^/  /'
  exit 1
fi
echo "PASS: ${#files[@]} C++ files formatted"
