#!/usr/bin/env bash
# Lesson texts are read by students: they cite papers by author and year, never by the
# project's seed numbers ("seed 004") or C++ symbols ("sl::rtw::momentsFromTop").
# usage: lesson_texts_cite_authors.sh <repository root>
set -euo pipefail
root=$1
shopt -s nullglob
lessons=("$root"/scenes/lessons/*.json)
(( ${#lessons[@]} >= 10 )) || { echo "FAIL: only ${#lessons[@]} lessons found"; exit 1; }
fail=0
for f in "${lessons[@]}"; do
  if hits=$(grep -oE '.{0,30}(seed [0-9]{3}|[A-Za-z_]+::[A-Za-z_]+).{0,20}' "$f"); then
    echo "FAIL: $(basename "$f"): $hits"
    fail=1
  fi
done
(( fail == 0 )) && echo "PASS: ${#lessons[@]} lessons cite authors, no seed numbers or C++ symbols"
exit $fail
