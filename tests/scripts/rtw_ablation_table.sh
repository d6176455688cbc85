#!/usr/bin/env bash
# scripts/rtw-ablation-table.py writes its tables (--out) under the output policy: --out that
# is one of the CSVs it reads (named, or through a link), a FIFO or a folder is refused in one
# line (exit 2) with the CSV untouched; a run that fails half-way leaves the old tables whole.
# usage: rtw_ablation_table.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_ablation_table"
table=(python3 root/scripts/rtw-ablation-table.py out a b)
printf 'technique,params,camera,error_pct\nrtw-backward,resolution=512,path,1.0\n' \
  >"$box/out/ablation-a.csv"
cp "$box/out/ablation-a.csv" "$box/out/ablation-b.csv"
csv=$(cat "$box/out/ablation-a.csv")

expect_refused "--out names a CSV it reads" "is the same file as the CSV 'out/ablation-b.csv'" \
  "${table[@]}" --out out/ablation-b.csv
expect_content "--out names a CSV it reads" "$box/out/ablation-b.csv" "$csv"
expect_link_refused "--out links to a CSV it reads" "$box/out/link.md" "$box/out/ablation-a.csv" \
  "is the same file as the CSV 'out/ablation-a.csv'" "${table[@]}" --out out/link.md
mkfifo "$box/out/fifo.md"
expect_refused "--out is a FIFO" "'out/fifo.md' is a FIFO, not a regular file" \
  "${table[@]}" --out out/fifo.md
mkdir "$box/out/folder.md"
expect_refused "--out is a folder" "'out/folder.md' is a folder" "${table[@]}" --out out/folder.md

# A run that fails half-way (scene c has no CSV): the old tables stay whole.
echo old >"$box/out/ablation.md"
if (cd "$box" && python3 root/scripts/rtw-ablation-table.py out a c --out out/ablation.md) \
  >/dev/null 2>&1; then
  failed "a missing CSV: the run succeeded"
fi
expect_content "a run that failed half-way" "$box/out/ablation.md" old
expect_no_temporary "a run that failed half-way" "$box/out"

# A good run writes the tables.
expect_good_run "a good run" "$box/out/ablation.md" '^\*\*`b`\*\*' \
  "${table[@]}" --out out/ablation.md
finish
