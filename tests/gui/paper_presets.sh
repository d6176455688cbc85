#!/usr/bin/env bash
# Every preset in scenes/papers (each paper's method as written) opens in the GUI as the
# Papers menu opens it (the same loader as --lesson FILE): the window renders the preset's
# scene with its technique, and every parameter of the preset has the preset's value in the
# frame the window rendered (published.json's "params", as the Parameters dock shows them;
# DA-RTW's gates also as published numbers). A preset whose parameters were dropped fails.
# usage: paper_presets.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/paper_presets
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

fail=0
n=0
for preset in "$here"/../../scenes/papers/*.json; do
  name=$(basename "$preset" .json)
  n=$((n + 1))
  dir=$out/$name
  rc=0
  timeout 300 "$app" --lesson "$preset" --grab "$dir" --grab-after 4 \
    >"$out/$name.out" 2>"$out/$name.err" || rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "FAIL: $name: shadowlab exited with $rc; stderr:"
    tail -n 20 "$out/$name.err"
    fail=1
    continue
  fi
  python3 - "$preset" "$dir/published.json" <<'PY' || fail=1
import json, sys
preset = json.load(open(sys.argv[1]))
pub = json.load(open(sys.argv[2]))
name = sys.argv[1].rsplit("/", 1)[-1]
ok = True
for key in ("scene", "technique"):
    if pub.get(key) != preset[key]:
        print(f"FAIL: {name}: {key} {pub.get(key)!r}, the preset says {preset[key]!r}")
        ok = False
numbers = pub.get("numbers", {})
params = pub.get("params", {})


def same(got, want):
    """Numbers as numbers (512 == 512.0), on/off as 1/0, names as text."""
    names = {"on": 1.0, "off": 0.0, "true": 1.0, "false": 0.0}
    try:
        g = names.get(str(got), None)
        g = float(got) if g is None else g
        w = names.get(str(want), None)
        w = float(want) if w is None else w
        return abs(g - w) <= 1e-6 * max(1.0, abs(w))
    except ValueError:
        return str(got) == str(want)


checked = 0
for key, value in preset.get("params", {}).items():
    if key not in params:
        print(f"FAIL: {name}: the window has no parameter {key}")
        ok = False
        continue
    checked += 1
    if not same(params[key], value):
        print(f"FAIL: {name}: {key} = {params[key]} in the window, the preset says {value}")
        ok = False
    # A choice (a name) is published as its index in the choice list: the window's own value
    # above is the check for it.
    named = isinstance(value, str) and value not in ("on", "off", "true", "false")
    if named:
        try:
            float(value)
            named = False
        except ValueError:
            pass
    if key in numbers and not named and not same(numbers[key], value):
        print(f"FAIL: {name}: {key} published as {numbers[key]}, the preset says {value}")
        ok = False
print(f"{name}: {preset['technique']} on {preset['scene']}, {checked} parameters as the preset "
      f"sets them, error {pub.get('error_pct')}")
sys.exit(0 if ok else 1)
PY
  python3 "$here/pngstats.py" --min-colors 32 --min-stddev 8 "$dir/viewport.png" || fail=1
done
[[ $n -ge 1 ]] || { echo "FAIL: no presets in scenes/papers"; fail=1; }
[[ $fail -eq 0 ]] && echo "PASS"
exit $fail
