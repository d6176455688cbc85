#!/usr/bin/env bash
# scripts/rtw-ablation.sh under the output policy, with a stub shadowlab-cli: its tables
# (ablation.md) as a FIFO, or as a link to a CSV of the same run, are refused in one line
# (exit 2) before the first bench; a table run that fails (no CSV) leaves the old tables whole.
# usage: rtw_ablation.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_ablation"
export SHADOWLAB_CLI=$stub_cli

mkfifo "$box/out/ablation.md"
expect_refused "the tables are a FIFO" "'$box/out/ablation.md' is a FIFO, not a regular file" \
  root/scripts/rtw-ablation.sh "$box/out" diagonal
rm "$box/out/ablation.md"

echo "a CSV of an earlier run" >"$box/out/ablation-diagonal.csv"
ln -s ablation-diagonal.csv "$box/out/ablation.md"
expect_refused "the tables link to a CSV of the run" \
  "is the same file as the CSV '$box/out/ablation-diagonal.csv'" \
  root/scripts/rtw-ablation.sh "$box/out" diagonal
expect_content "the tables link to a CSV of the run" "$box/out/ablation-diagonal.csv" \
  "a CSV of an earlier run"
rm "$box/out/ablation.md"

mkdir "$box/out/ablation-corridor.png"
expect_refused "a chart is a folder" "'$box/out/ablation-corridor.png' is a folder" \
  root/scripts/rtw-ablation.sh "$box/out" diagonal corridor
rmdir "$box/out/ablation-corridor.png"

# The benches write no CSV: the tables fail, the old ones stay whole.
echo old >"$box/out/ablation.md"
rm -f "$box/out/ablation-diagonal.csv"
if STUB_NO_CSV=1 timeout 20 "$box/root/scripts/rtw-ablation.sh" "$box/out" diagonal \
  >/dev/null 2>&1; then
  failed "no CSV: the run succeeded"
fi
expect_content "the tables failed" "$box/out/ablation.md" old
expect_no_temporary "the tables failed" "$box/out"

expect_good_run "a good run" "$box/out/ablation.md" '^\*\*`diagonal`\*\*' \
  root/scripts/rtw-ablation.sh "$box/out" diagonal
finish
