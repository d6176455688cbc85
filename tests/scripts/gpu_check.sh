#!/usr/bin/env bash
# scripts/gpu-check.sh checks, before its first step, every file it will write under --out: a
# gpu-check.csv that is a folder (a rename would move the table into it), a raw log that is a
# FIFO (a redirection would block), a --out that is a file: refused in one line (exit 2), no
# shadowlab-cli run. A good dry run with stub binaries writes both tables and leaves no
# temporary file.
# usage: gpu_check.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/gpu_check"
make_stub=$box/shadowlab-make-scenes
cat >"$make_stub" <<'STUB'
#!/usr/bin/env bash
echo "make-scenes $*" >>"$(dirname "$0")/cli.calls"
echo "wrote $2: 20000 triangles, stub"
STUB
chmod +x "$make_stub"
check=(root/scripts/gpu-check.sh --dry-run --cli "$stub_cli" --make-scenes "$make_stub")

mkdir -p "$box/out/run/gpu-check.csv"
expect_refused "gpu-check.csv is a folder" "'$box/out/run/gpu-check.csv' is a folder" \
  "${check[@]}" --out "$box/out/run"
if [[ -z $(ls -A "$box/out/run/gpu-check.csv") ]]; then
  ok "gpu-check.csv is a folder: nothing moved into it"
else
  failed "gpu-check.csv is a folder: it now holds $(ls -A "$box/out/run/gpu-check.csv")"
fi
rmdir "$box/out/run/gpu-check.csv"
mkdir -p "$box/out/run/raw" && mkfifo "$box/out/run/raw/bench.log"
expect_refused "raw/bench.log is a FIFO" "'$box/out/run/raw/bench.log' is not a regular file" \
  "${check[@]}" --out "$box/out/run"
rm -f "$box/out/run/raw/bench.log"
echo keep >"$box/out/file"
expect_refused "--out is a file" "--out '$box/out/file' is not a folder" \
  "${check[@]}" --out "$box/out/file"
expect_content "--out is a file" "$box/out/file" keep

expect_good_run "a good dry run" "$box/out/run/gpu-check.md" "GPU check" \
  "${check[@]}" --out "$box/out/run"
if grep -q '^table,name' "$box/out/run/gpu-check.csv" 2>/dev/null; then
  ok "a good dry run: gpu-check.csv written"
else
  failed "a good dry run: no gpu-check.csv"
fi
finish
