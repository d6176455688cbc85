#!/usr/bin/env bash
# Hostile inputs that are not glTF (issue 14): presets, suites and chart CSVs past the limits
# (devices, FIFOs, oversized files, JSON nested a million levels deep, a CSV with one
# enormous line, too many rows, long or numerous parameters, a row with the wrong number of
# fields). Every one exits 2 within a few seconds with one line naming the file and the
# limit. The inputs are generated here, never committed.
set -uo pipefail
cli=$1 out=$3/input-limits
rm -rf "$out" && mkdir -p "$out"
cd "$out" || exit 1
fail=0

# expect LINE CMD...: exit 2 within 20 s, stderr's last line exactly LINE.
expect() {
  local want=$1 err rc line
  shift
  err=$(timeout 20 "$cli" "$@" 2>&1 >/dev/null)
  rc=$?
  line=$(printf '%s\n' "$err" | tail -n 1)
  if [ $rc -ne 2 ] || [ "$line" != "$want" ]; then
    printf 'FAIL: %s exited %s (expected 2) saying:\n  %s\nexpected:\n  %s\n' \
      "$*" "$rc" "${line:0:400}" "$want"
    fail=1
  fi
}

p=shadowlab-cli
refused="not a regular file: refused (only regular files are read)"

# ---- presets and suites: JSON readers --------------------------------------------------
python3 - <<'PY'
open("deep.json", "w").write('{"a":' + "[" * 1000000 + "]" * 1000000 + "}")
# A quote inside a comment must not hide the nesting after it.
open("deep-comment.json", "w").write('/* " */ {"a":' + "[" * 100000 + "]" * 100000 + "}")
# 64 levels are fine for the depth check (the file is then refused for its content).
open("depth64.json", "w").write('{"a":' + "[" * 63 + "]" * 63 + "}")
PY
truncate -s 17M big.json
mkfifo pipe.json

for mode in preset suite; do
  run() {
    if [ $mode = preset ]; then
      expect "$p: --preset: $1" render --preset "$2" --size 64x36 --out "$out/p.png"
    else
      expect "$p: $1" stability --suite "$2" --json "$out/s.json"
    fi
  }
  run "deep.json: nested deeper than 64 levels (at byte 68): refused (kMaxJsonInputDepth)" deep.json
  run "deep-comment.json: nested deeper than 64 levels (at byte 76): refused (kMaxJsonInputDepth)" \
    deep-comment.json
  run "big.json: is 17825792 bytes, over the limit of 16 MiB per file (kMaxJsonInputBytes)" big.json
  run "pipe.json: is a FIFO, $refused" pipe.json
  run "/dev/zero: is a character device, $refused" /dev/zero
  run "$out: is a directory, $refused" "$out"
  run "missing.json: file not found" missing.json
done
# At the limit the depth check passes; the reader then names what is wrong.
err=$(timeout 20 "$cli" stability --suite depth64.json --json "$out/s.json" 2>&1 >/dev/null)
if [[ "$err" == *kMaxJsonInputDepth* ]]; then echo "FAIL: 64 levels refused: $err"; fail=1; fi

# ---- chart --csv -------------------------------------------------------------------------
header="scene,camera,technique,params,label,frames,width,height,timing_method,total_ms,texels,bytes,error_pct,gl"
row() { printf 'plane-box,path0,uniform,%s,x,3,64,36,gpu,1.5,4096,16384,2.5,gl\n' "$1"; }
c() { expect "$p: $1" chart --csv "$2" --chart "$out/c.png"; }

{ echo "$header"; row "resolution=512"; head -c 2000000 /dev/zero | tr '\0' 'a'; echo; } >long-line.csv
c "long-line.csv:3: line of 2000000 bytes, over the limit of 1 MiB (kMaxCsvLineBytes)" long-line.csv

head -c 2000000 /dev/zero | tr '\0' 'a' >long-header.csv
c "long-header.csv:1: line of 2000000 bytes, over the limit of 1 MiB (kMaxCsvLineBytes)" \
  long-header.csv

truncate -s 65M big.csv
c "big.csv: is 68157440 bytes, over the limit of 64 MiB per file (kMaxCsvBytes)" big.csv
c "pipe.json: is a FIFO, $refused" pipe.json
c "/dev/urandom: is a character device, $refused" /dev/urandom

python3 - "$header" <<'PY'
import sys
header = sys.argv[1]
def row(params, tech="uniform"):
    return f"plane-box,path0,{tech},{params},x,3,64,36,gpu,1.5,4096,16384,2.5,gl\n"
with open("rows.csv", "w") as f:  # 100,001 rows
    f.write(header + "\n" + row("resolution=512") * 100001)
with open("long-params.csv", "w") as f:  # 5,000 long parameter strings (45 MB): refused at the first
    f.write(header + "\n" + row("resolution=512"))
    f.write(row(" ".join(f"k{i}=" + "v" * 40 for i in range(200))) * 5000)
with open("many-params.csv", "w") as f:  # 65 short parameters
    f.write(header + "\n" + row(" ".join(f"k{i}=1" for i in range(65))))
with open("fields.csv", "w") as f:
    f.write(header + "\n" + row("resolution=512") + row("resolution=1024").replace(",x,", ",x,y,"))
with open("number.csv", "w") as f:
    f.write(header + "\n" + row("resolution=512") + row("a=1").replace(",1.5,", ",fast,"))
# Many rows within the limits: charted in linear time (was quadratic in the rows).
with open("wide.csv", "w") as f:
    f.write(header + "\n")
    for i in range(20000):
        f.write(row(" ".join(f"k{j}={i % 7 + j}" for j in range(60)), tech=f"t{i % 3}"))
PY
c "rows.csv:100002: more than 100000 rows: refused (kMaxCsvRows)" rows.csv
c "long-params.csv:3: params of 9089 bytes, over the limit of 4096 (kMaxCsvParamsBytes)" \
  long-params.csv
c "many-params.csv:2: more than 64 parameters in params: refused (kMaxCsvParams)" many-params.csv
c "fields.csv:3: 15 fields, the header has 14" fields.csv
c "number.csv:3: total_ms: expected a number, got 'fast'" number.csv

start=$SECONDS
if ! timeout 60 "$cli" chart --csv wide.csv --chart "$out/wide.png" >/dev/null 2>"$out/wide.err"; then
  # A build without Qt Charts says so; anything else is a failure.
  if ! grep -q "without Qt Charts" "$out/wide.err"; then
    echo "FAIL: wide.csv: $(tail -n 1 "$out/wide.err")"; fail=1
  fi
fi
if [ $((SECONDS - start)) -gt 30 ]; then echo "FAIL: wide.csv took $((SECONDS - start)) s"; fail=1; fi

[ $fail -eq 0 ] && echo "ok: hostile presets, suites and CSVs are refused naming the file and the limit"
exit $fail
