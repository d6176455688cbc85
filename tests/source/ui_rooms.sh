#!/usr/bin/env bash
# ui/ is grouped by concern (service/, view/, window/, teaching/, launch/, panels/…):
# at most 10 files at its root, so that a newcomer finds a room by its name, not in a heap.
# usage: ui_rooms.sh <repository root>
set -euo pipefail
root=$1
mapfile -t files < <(find "$root/ui" -maxdepth 1 -type f -printf '%f\n' | sort)
if (( ${#files[@]} > 10 )); then
  echo "FAIL: ui/ holds ${#files[@]} files at its root (at most 10); put them in a room:"
  printf '  %s\n' "${files[@]}"
  exit 1
fi
echo "ui/ root: ${#files[@]} files (${files[*]})"
