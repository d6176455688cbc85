#!/usr/bin/env bash
# Fuzzes the readers of untrusted files with libFuzzer: builds tests/fuzz in
# build-fuzz/ (clang, ASan + UBSan), then runs each target for SECONDS (default 600), one
# after the other, at the lowest CPU priority. Prints each target's executions; fails on any
# crash, leak, timeout (-timeout=5 s per input), memory blow-up (-rss_limit_mb=2048) or
# message that is not one bounded line naming the file.
#   scripts/fuzz.sh [SECONDS] [TARGET...]    TARGET: gltf json chart_csv (default: all)
# SECONDS 0 only builds. FUZZ_MAX_LEN: the largest input libFuzzer makes (default 262144, the
# size of the largest seed; smaller runs faster on the small inputs).
# The corpora grow in build-fuzz/corpus/TARGET (kept between runs); each run also reads the
# seeds, copied from the repository at run time (tests/data, scenes, lessons, suites,
# tests/fixtures/hostile, tests/fuzz/seeds). A finding is saved as
# build-fuzz/findings/TARGET-crash-...; reproduce it with build-fuzz/tests/fuzz/fuzz_TARGET FILE.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
seconds=${1:-600}
[ $# -gt 0 ] && shift
targets=("$@")
((${#targets[@]})) || targets=(gltf json chart_csv)
for t in "${targets[@]}"; do
  case $t in gltf | json | chart_csv) ;;
  *) echo "fuzz.sh: unknown target '$t' (targets: gltf json chart_csv)" >&2; exit 2 ;;
  esac
done
[[ $seconds =~ ^[0-9]+$ ]] || { echo "fuzz.sh: SECONDS must be a number, got '$seconds'" >&2; exit 2; }

build=build-fuzz
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B $build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSHADOWLAB_FUZZ=ON -DSHADOWLAB_GUI=OFF -DSHADOWLAB_BUILD_TESTS=OFF "${launcher[@]}" \
  >/dev/null
cmake --build $build -j2 --target "${targets[@]/#/fuzz_}"
[ "$seconds" -eq 0 ] && exit 0

# seeds TARGET DIR: copies the target's seed files into DIR.
seeds() {
  local files=()
  case $1 in
  gltf) files=(tests/data/*.gltf tests/data/*.glb scenes/*.gltf tests/fixtures/hostile/*.gltf
               tests/fixtures/hostile/*.glb) ;;
  json) files=(tests/data/suites/*.json scenes/lessons/*.json
               scenes/suites/*.json tests/fixtures/hostile/*.json) ;;
  chart_csv) files=(tests/fixtures/hostile/*.csv) ;;
  esac
  files+=(tests/fuzz/seeds/"$1"/*)
  for f in "${files[@]}"; do [ -f "$f" ] && cp "$f" "$2/"; done
  return 0
}

fail=0
summary=()
for t in "${targets[@]}"; do
  corpus=$build/corpus/$t seed=$build/seeds/$t log=$build/logs/$t.log
  rm -rf "$seed" && mkdir -p "$corpus" "$seed" "$build/logs" "$build/findings"
  seeds "$t" "$seed"
  dict=()
  [ -f "tests/fuzz/$t.dict" ] && dict=(-dict="$root/tests/fuzz/$t.dict")
  echo "fuzz.sh: fuzz_$t for $seconds s (log: $log)"
  rc=0 start=$SECONDS
  nice -n 19 "$build/tests/fuzz/fuzz_$t" "${dict[@]}" -max_total_time="$seconds" -timeout=5 \
    -rss_limit_mb=2048 -max_len="${FUZZ_MAX_LEN:-262144}" -print_final_stats=1 \
    -artifact_prefix="$build/findings/$t-" "$corpus" "$seed" >"$log" 2>&1 || rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  line="fuzz_$t: ${execs:-?} executions in $((SECONDS - start)) s, corpus $(ls "$corpus" | wc -l) files"
  if [ $rc -ne 0 ]; then
    fail=1
    line+=", FAILED (exit $rc): $(ls -t $build/findings/$t-* 2>/dev/null | head -n 1)"
    echo "---- $log (last 40 lines)"
    tail -n 40 "$log"
  fi
  summary+=("$line")
done
printf '%s\n' "${summary[@]}"
exit $fail
