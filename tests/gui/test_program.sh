#!/usr/bin/env bash
# The GUI tests live outside the product: the shipped shadowlab has no test mode (an old
# --self-test is an unknown option, and the binary holds no "self-test" string), and
# shadowlab-gui-tests refuses a test name it does not know (exit 2, naming the known ones)
# instead of running some default test. No window is needed for any of this.
# usage: test_program.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/test_program
rm -rf "$out" && mkdir -p "$out"

if grep -aqi 'self-test' "$app"; then
  echo "FAIL: $app contains the string 'self-test'"
  exit 1
fi
echo "ok   shadowlab holds no 'self-test'"

rc=0
env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM "$app" --self-test params \
  >"$out/shadowlab.stdout" 2>"$out/shadowlab.stderr" || rc=$?
[[ $rc -eq 2 ]] || { echo "FAIL: shadowlab --self-test exited $rc, expected 2"; exit 1; }
grep -qi "unknown option" "$out/shadowlab.stderr" ||
  { echo "FAIL: shadowlab --self-test: no 'unknown option' line:"; cat "$out/shadowlab.stderr"; exit 1; }
echo "ok   shadowlab --self-test: $(head -n1 "$out/shadowlab.stderr")"

for args in "--test no-such-test" "--test=no-such-test=x" ""; do
  rc=0
  # shellcheck disable=SC2086
  env -u DISPLAY -u WAYLAND_DISPLAY "$tests" $args --scene default \
    >"$out/tests.stdout" 2>"$out/tests.stderr" || rc=$?
  [[ $rc -eq 2 ]] || { echo "FAIL: shadowlab-gui-tests '$args' exited $rc, expected 2"; exit 1; }
  grep -q "known: params" "$out/tests.stderr" ||
    { echo "FAIL: '$args': the known tests are not named:"; cat "$out/tests.stderr"; exit 1; }
  if [[ -n $args ]]; then
    grep -q "unknown test 'no-such-test'" "$out/tests.stderr" ||
      { echo "FAIL: '$args': the unknown name is not named:"; cat "$out/tests.stderr"; exit 1; }
  fi
  echo "ok   shadowlab-gui-tests '$args': $(cut -c1-100 "$out/tests.stderr" | head -n1)"
done
echo "PASS"
