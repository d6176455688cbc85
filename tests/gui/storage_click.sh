#!/usr/bin/env bash
# The Storage factor panel's hemisphere (issue 10): a click on the disk moves the light to the
# direction there — the one algo/partition's Fig. 7 frame of this camera gives for that disk
# point — the status bar says so, and the panel re-analyses with the light's mark under the
# click; a click outside the disk keeps the light. PNGs of the window after each click.
# usage: storage_click.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/storage_click
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

run_gui_test "GUI test storage-click" 300 "$out/storage_click" \
  "$tests" --scene diagonal --technique lispsm --test "storage-click=$out"
for n in 1 2; do
  python3 "$here/pngstats.py" --min-colors 32 --min-stddev 8 "$out/storage-click-$n.png"
done
echo "PASS"
