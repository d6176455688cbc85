#!/usr/bin/env bash
# shadowlab-cli stability: the per-frame JSON (rotation_deg, e_x, held, mask_changed_pct) and
# its summary; a static uniform map never changes, an orbiting camera changes the mask; a
# technique with a rotation (da-rtw, when registered) settles and then holds it.
set -euo pipefail
cli=$1 out=$3/stability
mkdir -p "$out"
"$cli" stability --scene diagonal --technique uniform --frames 6 --size 320x180 \
  --json "$out/static.json" 2>/dev/null
"$cli" stability --scene diagonal --technique uniform --set resolution=1024 --frames 4 \
  --orbit 0.5 --reference --size 320x180 --json "$out/orbit.json" 2>/dev/null
have_da=0
techniques=$("$cli" list)
if grep -q '^  da-rtw ' <<<"$techniques"; then
  have_da=1
  "$cli" stability --scene diagonal --camera row-end --technique da-rtw --set resolution=512 \
    --frames 16 --size 320x180 --json "$out/da-rtw.json" 2>/dev/null
fi
python3 - "$out" "$have_da" <<'PY'
import json, sys
out, have_da = sys.argv[1], sys.argv[2] == "1"
s = json.load(open(f"{out}/static.json"))
for k in ["scene", "technique", "params", "frames", "per_frame", "summary"]:
    assert k in s, f"missing {k}"
assert len(s["per_frame"]) == 6
for f in s["per_frame"]:
    for k in ["frame", "rotation_deg", "e_x", "held", "mask_changed_pct"]:
        assert k in f, f"frame lacks {k}: {f}"
    # No rotation: reported as 0 degrees, e_x 1, held.
    assert f["rotation_deg"] == 0 and f["e_x"] == 1 and f["held"] is True, f
    # The first frame has none before it: its change is not measured (null), never 0.
    assert f["mask_changed_pct"] == (None if f["frame"] == 0 else 0), f
for k in ["rotation_changes", "max_rotation_step_deg", "mask_change_frames"]:
    assert k in s["summary"], f"summary lacks {k}"
assert s["summary"]["mask_change_frames"] == 0 and s["summary"]["rotation_changes"] == 0

o = json.load(open(f"{out}/orbit.json"))
assert o["orbit_deg_per_frame"] == 0.5
assert o["summary"]["mask_change_frames"] == 3, o["summary"]  # the camera moves every frame
assert all("error_pct" in f and "flicker_pct" in f for f in o["per_frame"])
msg = f"ok: static uniform 0 changes; orbit changes {o['summary']['max_mask_changed_pct']:.3f}% max"

if have_da:
    d = json.load(open(f"{out}/da-rtw.json"))
    sm = d["summary"]
    assert d["has_rotation"], "da-rtw publishes no rotation.deg"
    # The rotation is set in the first frames and then held; the mask then stops changing.
    assert sm["last_rotation_change_frame"] <= 4, sm
    assert sm["last_mask_change_frame"] <= 5, sm
    msg += (f"; da-rtw: {sm['rotation_changes']} rotation changes (last at frame "
            f"{sm['last_rotation_change_frame']}), rotation {d['per_frame'][-1]['rotation_deg']:.2f} deg")
print(msg)
PY
