#!/usr/bin/env bash
# A scene file that does not exist: --grab exits non-zero with a message naming the file,
# and writes no images. A lesson whose scene does not exist is a problem of the grab too: it
# exits 1 with a "grab failed:" line naming the file (it exited 0, grabbing a blank view); its
# published.json has the error and frame time n/a (null) with the reason (no scene), never 0.
# usage: bad_scene.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1 data=$2
out=$3/bad_scene
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

missing=/nonexistent.gltf
rc=0
timeout 120 "$app" --scene "$missing" --grab "$out/grab" >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
cat "$out/stderr.txt"
[[ $rc -ne 0 ]] || { echo "FAIL: exit code 0 for a missing scene"; exit 1; }
[[ $rc -ne 124 ]] || { echo "FAIL: timed out"; exit 1; }
grep -qF "$missing" "$out/stderr.txt" || { echo "FAIL: stderr does not name $missing"; exit 1; }
[[ ! -e "$out/grab/window.png" ]] || { echo "FAIL: window.png written anyway"; exit 1; }

rc=0
timeout 300 "$app" --lesson "$data/presets/grab-missing-scene.json" --grab "$out/lesson" \
  --grab-after 2 >"$out/lesson.stdout" 2>"$out/lesson.stderr" || rc=$?
cat "$out/lesson.stderr"
[[ $rc -eq 1 ]] || { echo "FAIL: a lesson whose scene is missing: exit $rc, expected 1"; exit 1; }
grep -qE "^shadowlab: grab failed: .*no-such-folder/no-such-scene\.gltf" "$out/lesson.stderr" ||
  { echo "FAIL: no 'grab failed' line naming the lesson's scene"; exit 1; }
# With no scene the frame fails: its error and time are n/a with the reason, never 0.
python3 - "$out/lesson/published.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
assert "error_pct" in p and p["error_pct"] is None, f"no scene: error_pct {p.get('error_pct')!r}"
assert p.get("error_unmeasured") == "the frame failed: no scene loaded", p.get("error_unmeasured")
assert p.get("error_readout") == "error n/a (the frame failed: no scene loaded)", p.get("error_readout")
assert p.get("frame_ms", 0) is None and p.get("frame_failure") == "no scene loaded", p.get("frame_ms")
print(f"no scene: error_pct null, {p['error_unmeasured']}; status line {p['error_readout']!r}")
PY
echo "PASS"
