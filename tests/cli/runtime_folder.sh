#!/usr/bin/env bash
# The CLI's Qt runtime folder (charts need Qt; without XDG_RUNTIME_DIR the CLI makes one in
# the temporary folder): a symbolic link planted under its name is never followed — the file
# it points to keeps its mode (the CLI made the folder 0700 through the link) — and the chart
# is still drawn, in a private folder of its own.
set -uo pipefail
cli=$1 out=$3/runtime_folder
rm -rf "$out" && mkdir -p "$out/tmp"
fail=0
cat >"$out/in.csv" <<'CSV'
scene,camera,technique,params,label,frames,width,height,timing_method,total_ms,texels,bytes,error_pct,gl
plane-box,path0,uniform,resolution=512,x,3,64,36,gpu,1.5,4096,16384,2.5,gl
plane-box,path0,uniform,resolution=1024,x,3,64,36,gpu,2.5,4096,65536,1.5,gl
CSV
echo "not a folder" >"$out/victim" && chmod 644 "$out/victim"
ln -s "$out/victim" "$out/tmp/shadowlab-runtime-$(id -u)"
rc=0
env -u XDG_RUNTIME_DIR TMPDIR="$out/tmp" "$cli" chart --csv "$out/in.csv" --chart "$out/c.png" \
  >/dev/null 2>"$out/err.txt" || rc=$?
if [ $rc -eq 2 ] && grep -q "charts" "$out/err.txt"; then
  echo "ok: a build without charts (nothing to check)"; exit 0
fi
[ $rc -eq 0 ] || { echo "FAIL: chart exited $rc"; cat "$out/err.txt"; fail=1; }
mode=$(stat -c %a "$out/victim")
[ "$mode" = 644 ] || { echo "FAIL: the link's target changed mode to $mode"; fail=1; }
[ -L "$out/tmp/shadowlab-runtime-$(id -u)" ] || { echo "FAIL: the planted link was replaced"; fail=1; }
[ -s "$out/c.png" ] || { echo "FAIL: no chart"; fail=1; }
[ $fail -eq 0 ] && echo "ok: the planted link kept its target's mode 644; chart drawn"
exit $fail
