#!/usr/bin/env bash
# Out-of-range and unknown parameters / techniques on the command line: --grab exits with
# 2 and one stderr line naming the parameter and its range (or the known ids).
# usage: bad_param.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/bad_param
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

# expect_exit2 NAME PATTERN... -- ARGS: runs shadowlab, wants exit 2 and every pattern.
expect_exit2() {
  local name=$1
  shift
  local patterns=()
  while [[ $1 != "--" ]]; do patterns+=("$1"); shift; done
  shift
  local rc=0
  timeout 120 "$app" "$@" --grab "$out/$name" >"$out/$name.stdout" 2>"$out/$name.stderr" || rc=$?
  echo "[$name] exit $rc: $(cat "$out/$name.stderr")"
  [[ $rc -eq 2 ]] || { echo "FAIL [$name]: expected exit 2, got $rc"; exit 1; }
  [[ $(wc -l <"$out/$name.stderr") -eq 1 ]] || { echo "FAIL [$name]: expected one stderr line"; exit 1; }
  for p in "${patterns[@]}"; do
    grep -qF -- "$p" "$out/$name.stderr" || { echo "FAIL [$name]: stderr lacks '$p'"; exit 1; }
  done
  [[ ! -e "$out/$name/window.png" ]] || { echo "FAIL [$name]: window.png written anyway"; exit 1; }
}

expect_exit2 range "resolution" "999999" ".." -- --technique uniform --set resolution=999999
expect_exit2 unknown_key "no.such.key" "resolution" -- --technique uniform --set no.such.key=1
expect_exit2 not_a_number "resolution" -- --technique uniform --set resolution=big
expect_exit2 technique "no-such-technique" "uniform" -- --technique no-such-technique
echo "PASS"
