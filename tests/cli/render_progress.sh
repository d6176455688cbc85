#!/usr/bin/env bash
# `render --frames N` shows progress (issue 14: `--frames 100000` showed nothing): the
# progress bar bench uses, on stderr; one frame stays quiet.
set -uo pipefail
cli=$1 out=$3/render-progress
rm -rf "$out" && mkdir -p "$out"
fail=0
render=(render --scene plane-box --technique uniform --set resolution=64 --size 16x16)

if "$cli" "${render[@]}" --frames 300 --out "$out/many.png" >"$out/many.stdout" 2>"$out/many.stderr"; then
  # Not a terminal: plain lines, the first frame's at once and the last one's always.
  head -n 1 "$out/many.stderr" | grep -qE '^render:   0% \(1/300\) frame 1/300, [0-9:]+ elapsed, about [0-9:]+ left$' ||
    { echo "FAIL: no first progress line:"; head -n 1 "$out/many.stderr"; fail=1; }
  grep -qE '^render: 100% \(300/300\) frame 300/300, [0-9:]+ elapsed, about 0:00 left$' "$out/many.stderr" ||
    { echo "FAIL: no final progress line:"; cat "$out/many.stderr"; fail=1; }
  tail -n 1 "$out/many.stderr" | grep -qE '^render: done, 300 runs in [0-9:]+$' ||
    { echo "FAIL: no done line:"; tail -n 1 "$out/many.stderr"; fail=1; }
  grep -q '^uniform on plane-box: ' "$out/many.stdout" || { echo "FAIL: no result line"; fail=1; }
else
  echo "FAIL: render --frames 300:"; cat "$out/many.stderr"; fail=1
fi

"$cli" "${render[@]}" --out "$out/one.png" >/dev/null 2>"$out/one.stderr" ||
  { echo "FAIL: render one frame"; fail=1; }
[ ! -s "$out/one.stderr" ] || { echo "FAIL: one frame printed progress:"; cat "$out/one.stderr"; fail=1; }

[ $fail -eq 0 ] && echo "render progress: ok"
exit $fail
