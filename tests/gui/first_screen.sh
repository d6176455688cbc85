#!/usr/bin/env bash
# The first screen: `shadowlab` with no options and no settings of its own opens on DA-RTW,
# and the design's panels (Importance map, Moment mip chain, Covariance with its principal
# axis, Warp functions, Shadow map, Parameters) are in view and drew data; no panel in view
# shows its "publishes no ..." placeholder. `--technique uniform` closes the RTW panels and
# keeps the Shadow map. The `panels` GUI test switches techniques in one window: a
# technique's own panels come, the ones it does not feed go, one opened by hand from
# View > Panels stays until it is closed.
# usage: first_screen.sh <shadowlab> <tests/data dir> <out dir> <shadowlab-gui-tests>
set -euo pipefail
app=$1
tests=$4
out=$3/first_screen
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out/config"
# A fresh settings file: nothing remembered (QSettings reads $XDG_CONFIG_HOME).
export XDG_CONFIG_HOME="$out/config"
XVFB_SCREEN=1920x1080x24 start_xvfb

grab() {  # grab <dir> <options...>
  local dir=$1 rc=0
  shift
  timeout 300 "$app" "$@" --grab "$out/$dir" --grab-after 8 \
    >"$out/$dir.stdout" 2>"$out/$dir.stderr" || rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "FAIL: shadowlab $* exited with $rc; stderr:"
    cat "$out/$dir.stderr"
    exit 1
  fi
}
grab default
grab uniform --technique uniform
[[ -z "$(ls -A "$out/config")" ]] || { echo "FAIL: a grab wrote settings"; ls -R "$out/config"; exit 1; }

design="importance moments covariance warp shadowmap"
python3 "$here/pngstats.py" --min-colors 64 --min-stddev 8 --min-size 1200x800 \
  "$out/default/window.png" "$out/uniform/window.png"
for p in $design; do
  python3 "$here/pngstats.py" --min-colors 300 --min-stddev 15 "$out/default/panel-$p.png"
done

python3 - "$out/default/published.json" "$out/uniform/published.json" <<'PY'
import json, math, sys
first, uniform = (json.load(open(p)) for p in sys.argv[1:3])
fail = []
def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok: fail.append(what)

design = ["importance", "moments", "covariance", "warp", "shadowmap"]
view, empty, drawn = first["docks_in_view"], first["placeholders"], first["panels"]
check(first["technique"] == "da-rtw" and first["published_technique"] == "da-rtw",
      f"the first screen shows da-rtw (technique {first['technique']})")
check(first["scene"] == "default", f"on the default scene ({first['scene']})")
for p in design + ["parameters"]:
    check(p in view, f"first screen: {p} in view")
for p in view:
    check(p not in empty, f"first screen: {p} shows data" + (f" (placeholder: {empty[p]!r})" if p in empty else ""))
imp, mom, cov = drawn["importance"], drawn["moments"], drawn["covariance"]
im = first["images"].get("importance", [0, 0])
check(imp.get("width", 0) > 0 and [imp["width"], imp["height"]] == im[:2] and imp.get("max", 0) > 0,
      f"importance map {imp.get('width')}x{imp.get('height')}, max {imp.get('max')}")
check(mom.get("levels", 0) >= 2, f"moment chain: {mom.get('levels')} levels")
axis = cov.get("axis_deg")
check(isinstance(axis, (int, float)) and math.isfinite(axis) and cov.get("eigen.1", 0) > 0,
      f"covariance: principal axis {axis} deg, lambda1 {cov.get('eigen.1')}")
warp = drawn["warp"]
for a in ("x", "y"):
    check(warp.get(f"{a}.edges", 0) > 1 and warp[f"{a}.edges"] == first["curves"].get(f"warp.{a}"),
          f"warp functions: {warp.get(f'{a}.edges')} edges of warp.{a}")
sm = drawn["shadowmap"]
check(sm.get("warped") and sm.get("width", 0) > 0, f"shadow map: warped {sm.get('width')}x{sm.get('height')}")

view, empty = uniform["docks_in_view"], uniform["placeholders"]
check(uniform["technique"] == "uniform", f"--technique uniform shows uniform ({uniform['technique']})")
for p in ["importance", "moments", "covariance", "warp"]:
    check(p not in view, f"uniform: {p} not in view")
check("shadowmap" in view, "uniform: shadowmap in view")
for p in view:
    check(p not in empty, f"uniform: {p} shows data" + (f" (placeholder: {empty[p]!r})" if p in empty else ""))
sys.exit(1 if fail else 0)
PY
for p in importance moments covariance warp; do
  [[ ! -e "$out/uniform/panel-$p.png" ]] || { echo "FAIL: uniform grabbed the closed $p panel"; exit 1; }
done

run_gui_test "GUI test panels" 300 "$out/panels" "$tests" --test panels
echo "PASS"
