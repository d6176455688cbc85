#!/usr/bin/env bash
# The split view's own parameters (issue 15): the right half's resolution edited in its own
# panel changes its memory and error and not the left half's; "equal memory" picks the
# largest right resolution within the left half's bytes (one step more spends more), and
# matches again when the left side's memory changes. PNG in <out>/split_params.
# usage: split_params.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/split_params
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test split-params" 240 "$out/split_params" \
  "$tests" --scene default --technique uniform --set resolution=1024 --test "split-params=$out"
echo "PASS"
