#!/usr/bin/env bash
# scripts/rtw-turns-table.py writes its chart (--svg) and tables (--out) under the output
# policy: a --svg that is one of the CSVs it reads, a --out that links to a prediction it
# reads, a FIFO and a folder are refused in one line (exit 2) with the inputs untouched; a good
# run writes both and leaves no temporary file.
# usage: rtw_turns_table.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/rtw_turns_table"
table=(python3 root/scripts/rtw-turns-table.py out)
csv='technique,params,camera,error_pct,rotation_deg
rtw-backward,resolution=64,camera 0,1.0,0
da-rtw,resolution=64 rotation.mode=fixed rotation.fixed_deg=0,camera 0,1.0,0
da-rtw,resolution=64 rotation.mode=fixed rotation.fixed_deg=15,camera 0,0.8,15
da-rtw,resolution=64,camera 0,0.9,10
da-rtw,resolution=64 rotation.mode=pca,camera 0,1.1,30'
echo "$csv" >"$box/out/turns-room@0-64.csv"
echo '{"published_curves": {}}' >"$box/out/prediction-room@0-64-edges.json"

expect_refused "--svg names a CSV it reads" \
  "--svg 'out/turns-room@0-64.csv' is the same file as the input 'out/turns-room@0-64.csv'" \
  "${table[@]}" --svg out/turns-room@0-64.csv
expect_content "--svg names a CSV it reads" "$box/out/turns-room@0-64.csv" "$csv"
expect_link_refused "--out links to a prediction it reads" "$box/out/tables.md" \
  "$box/out/prediction-room@0-64-edges.json" \
  "is the same file as the input 'out/prediction-room@0-64-edges.json'" \
  "${table[@]}" --out out/tables.md
mkfifo "$box/out/chart.svg"
expect_refused "--svg is a FIFO" "--svg 'out/chart.svg' is a FIFO, not a regular file" \
  "${table[@]}" --svg out/chart.svg
rm "$box/out/chart.svg"
mkdir "$box/out/chart.svg"
expect_refused "--svg is a folder" "--svg 'out/chart.svg' is a folder" \
  "${table[@]}" --svg out/chart.svg
rmdir "$box/out/chart.svg"
expect_refused "--svg and --out name one file" \
  "--svg 'out/./both' is the same file as --out 'out/both'" \
  "${table[@]}" --out out/both --svg out/./both

if (cd "$box" && "${table[@]}" --svg out/chart.svg --out out/tables.md) >/dev/null &&
  grep -q '<svg' "$box/out/chart.svg" && grep -q '`room`' "$box/out/tables.md"; then
  ok "a good run wrote the chart and the tables"
else
  failed "a good run: no chart or no tables"
fi
expect_no_temporary "a good run" "$box/out"
finish
