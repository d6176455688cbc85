#!/usr/bin/env bash
# compare for handouts (issue 15 item 5): the configurations given by --technique (bench's
# ID:KEY=V syntax) with --set, --camera and --light for all; --montage writes one labelled PNG
# (each configuration's image above its error image, error pixels dilated for print,
# configuration / texels / error / time under each, an optional zoom inset). A technique that cannot render the
# light, or an unknown one, is refused naming it; nothing is written. The montage is written
# atomically, and a write error exits 1 naming the file.
set -uo pipefail
cli=$1 out=$3/compare_montage
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
fail=0
ok() { echo "ok   $*"; }
bad() { echo "FAIL $*"; fail=1; }

"$cli" compare --scene corridor --camera start --technique uniform:resolution=1024 \
  --technique rtw-backward:resolution=512 --set pcf=0 --size 320x180 --out-dir "$out/cmp" \
  --montage "$out/montage.png" --inset 0.45,0.42,0.12,0.12,3 >"$out/stdout" 2>"$out/stderr" || bad "compare exited with $?: $(cat "$out/stderr")"
cat "$out/stdout"
[ "$(grep -c '^uniform resolution=1024 \|^rtw-backward resolution=512 ' "$out/stdout")" = 2 ] &&
  ok "two rows, one per configuration" || bad "rows: $(cat "$out/stdout")"
python3 - "$out" <<'PY' || fail=1
import json, struct, sys, zlib
out = sys.argv[1]
summary = json.load(open(f"{out}/cmp/summary.json"))
labels = [s["configuration"] for s in summary]
assert labels == ["uniform resolution=1024", "rtw-backward resolution=512"], labels
assert summary[0]["texels"] == 1024 * 1024, summary[0]["texels"]
for s in summary:
    assert s["error_pct"] is not None and s["error_pct"] >= 0 and s["total_ms"] > 0, s
# The montage: a PNG two cells wide (each 320 px plus margins), two images high plus text.
data = open(f"{out}/montage.png", "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
w, h = struct.unpack(">II", data[16:24])
assert 2 * 320 < w < 2 * 320 + 120 and 2 * 180 < h < 2 * 180 + 300, (w, h)
print(f"ok   montage {w}x{h}: {labels}")
PY
python3 "$here/../gui/pngstats.py" --min-colors 16 --min-stddev 8 "$out/montage.png" || fail=1

# Refusals, before any file is written.
err=$("$cli" compare --scene corridor --technique uniform --technique cube --size 64x36 --out-dir "$out/refused" \
  --montage "$out/refused.png" 2>&1 >/dev/null); rc=$?
[ $rc = 2 ] && grep -q "cube" <<<"$err" && ok "cube under a sun: exit 2: $err" || bad "cube: exit $rc: $err"
err=$("$cli" compare --scene corridor --technique nonesuch --size 64x36 --out-dir "$out/refused" 2>&1 >/dev/null); rc=$?
[ $rc = 2 ] && grep -q "nonesuch" <<<"$err" && ok "unknown technique: exit 2: $err" || bad "nonesuch: exit $rc: $err"
err=$("$cli" compare --scene corridor --technique uniform --size 64x36 --out-dir "$out/refused" \
  --montage "$out/refused.png" --inset 0.9,0.1,0.2,0.2 2>&1 >/dev/null); rc=$?
[ $rc = 2 ] && grep -q "inside the image" <<<"$err" && ok "inset outside the image: exit 2: $err" || bad "inset: exit $rc: $err"
[ ! -e "$out/refused.png" ] && [ -z "$(ls -A "$out/refused" 2>/dev/null)" ] && ok "nothing written by a refused run" || bad "a refused run wrote $(ls "$out/refused")"
# The montage is written like every output: a temporary file in its folder, renamed into place
# (an existing montage is replaced by another file, not overwritten in place; no temporary file
# is left); a write error exits 1 with one line naming the file, not 2 (bad input).
mkdir -p "$out/again"
echo "an older montage" >"$out/again/montage.png"
before=$(stat -c %i "$out/again/montage.png")
"$cli" compare --scene corridor --technique uniform --size 64x36 --out-dir "$out/again/cmp" \
  --montage "$out/again/montage.png" >/dev/null 2>&1 || bad "second montage: exit $?"
[ "$(stat -c %i "$out/again/montage.png")" != "$before" ] && head -c 4 "$out/again/montage.png" | grep -q PNG &&
  ok "the montage replaced by a rename" || bad "the montage was rewritten in place"
[ -z "$(ls -A "$out/again" | grep -v '^montage.png$\|^cmp$')" ] && ok "no temporary file left" ||
  bad "left in the folder: $(ls -A "$out/again")"
err=$("$cli" compare --scene corridor --technique uniform --size 64x36 --out-dir "$out/full" \
  --montage /dev/full 2>&1 >/dev/null); rc=$?
[ $rc = 1 ] && [ "$(wc -l <<<"$err")" = 1 ] && grep -qF "shadowlab-cli: /dev/full: cannot write (No space left on device)" <<<"$err" &&
  ok "a montage write error: exit 1 naming the file: $err" || bad "montage to /dev/full: exit $rc: $err"
[ $fail = 0 ] && echo PASS
exit $fail
