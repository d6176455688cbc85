#!/usr/bin/env bash
# The GUI on plane-box with rmsm and a pool too small for the frame (8 pages): the Pages
# panel draws the page table with its counts (published.json: what the panel drew: 8 levels,
# every pool page used, requests coarsened), and its PNG is a real picture. Then asm with a pool
# of 40 pages and 8 new pages a frame: the panel draws the cache's page table, and its cells
# counted by colour (allocated this frame / cached used / cached unused / evicted / requested,
# not allocated) are the published asm.* and pages.* numbers of the same frame.
# usage: grab_pages.sh <shadowlab> <tests/data dir> <out dir>
set -euo pipefail
app=$1
out=$3/grab_pages
here=$(cd "$(dirname "$0")" && pwd)
source "$here/xvfb.bash"
rm -rf "$out" && mkdir -p "$out"
start_xvfb

# grab NAME FRAMES ARGS...: the GUI on plane-box with ARGS grabbed after FRAMES frames into
# $out/NAME, its Pages panel a real picture.
grab() {
  local name=$1 frames=$2 rc=0
  shift 2
  timeout 300 "$app" --scene plane-box "$@" --grab "$out/$name" --grab-after "$frames" \
    >"$out/$name.stdout" 2>"$out/$name.stderr" || rc=$?
  if [[ $rc -ne 0 ]]; then
    echo "FAIL: shadowlab ($name) exited with $rc; stderr:"
    cat "$out/$name.stderr"
    exit 1
  fi
  python3 "$here/pngstats.py" --min-colors 3 --min-stddev 8 "$out/$name/panel-pages.png"
}

grab rmsm 3 --technique rmsm --set virtual.resolution=16384 --set pool.pages=8
python3 - "$out" <<'PY'
import json, sys
p = json.load(open(f"{sys.argv[1]}/rmsm/published.json"))["panels"]["pages"]
assert p["levels"] == 8 and p["pool"] == 8 and p["allocated"] <= 8, p
assert p["requested"] > 8 and p["coarsened"] > 0, p
print("ok: pages panel: 8 levels, pool of 8 used, %d requests coarsened" % p["coarsened"])
PY

grab asm 4 --technique asm --set virtual.resolution=16384 --set pool.pages=40 \
  --set asm.pages.per.frame=8
python3 - "$out" <<'PY'
import json, sys
j = json.load(open(f"{sys.argv[1]}/asm/published.json"))
p, n = j["panels"]["pages"], j["numbers"]
c = p["cells"]
assert p["cache"] and p["levels"] == 8 and p["pool"] == 40, p
# The frame grabbed is not the first: no coarse map rendered, every new page counted in asm.new.
assert c["new"] == n["asm.new"] and c["new"] <= 8, (c, n)
assert c["cached_hit"] == n["asm.hits"] and c["cached_hit"] > 0, (c, n)
assert c["new"] + c["cached_hit"] + c["cached_idle"] == n["pages.allocated"] == p["allocated"], (c, n)
assert c["evicted"] <= n["asm.evicted"], (c, n)
assert c["requested_waiting"] > 0, c  # the budget of 8 a frame leaves requests waiting
assert c["requested"] == c["fallback"] == c["coarsened"] == 0, c  # rmsm's states only
print("ok: pages panel (asm): %d new, %d cached used, %d unused, %d evicted, %d waiting" %
      (c["new"], c["cached_hit"], c["cached_idle"], c["evicted"], c["requested_waiting"]))
PY

# The iteration-cap preset (ASM's loop stopped by asm.iterations.cap 1 on diagonal): the cap
# stopped the first frame's loop; frames later (the cache converged since) the Pages panel still
# shows how many frames it stopped, and this frame's loop, as published.
rc=0
timeout 300 "$app" --lesson "$here/../../scenes/papers/001-asm-iteration-cap.json" \
  --grab "$out/asm-cap" --grab-after 1 >"$out/asm-cap.stdout" 2>"$out/asm-cap.stderr" || rc=$?
if [[ $rc -ne 0 ]]; then
  echo "FAIL: shadowlab (asm-cap) exited with $rc; stderr:"
  cat "$out/asm-cap.stderr"
  exit 1
fi
python3 - "$out" <<'PY'
import json, sys
j = json.load(open(f"{sys.argv[1]}/asm-cap/published.json"))
p, n = j["panels"]["pages"], j["numbers"]
assert n["asm.cap.stops"] >= 1 and n["param.asm.iterations.cap"] == 1, n
assert p["cap_stops"] == n["asm.cap.stops"], (p, n)
assert p["loop_stop"] == n["asm.stop"] and p["loop_requests_left"] == n["asm.requests.left"], (p, n)
print("ok: pages panel (asm, iteration cap): the cap stopped %d frames; this frame stop %d, "
      "%d pages still requested" % (n["asm.cap.stops"], n["asm.stop"], n["asm.requests.left"]))
PY
