#!/usr/bin/env bash
# A camera path whose keys start late (5-10 s): `render --path-at F` is F of the way from the
# first key to the last, so F = 0, 0.25 and 0.5 are three different cameras (sampling F times
# the last key's time gave the first key for all three).
set -uo pipefail
cli=$1 data=$2 out=$3/camera-paths
rm -rf "$out" && mkdir -p "$out"
fail=0
check() {  # check DESCRIPTION COMMAND...: passes when the command succeeds
  local what=$1; shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; fail=1; fi
}
# plane-box's path with every key time moved 5 s later.
here=$(cd "$(dirname "$0")" && pwd)
python3 - "$here/../../scenes/plane-box.gltf" "$out/late.gltf" <<'PY'
import base64, json, struct, sys
g = json.load(open(sys.argv[1]))
head, b64 = g["buffers"][0]["uri"].split(",", 1)
raw = bytearray(base64.b64decode(b64))
for acc in sorted({s["input"] for a in g["animations"] for s in a["samplers"]}):
    a = g["accessors"][acc]
    view = g["bufferViews"][a["bufferView"]]
    start, n = view.get("byteOffset", 0) + a.get("byteOffset", 0), a["count"]
    times = [t + 5 for t in struct.unpack("<%df" % n, raw[start:start + 4 * n])]
    raw[start:start + 4 * n] = struct.pack("<%df" % n, *times)
    a["min"], a["max"] = [min(times)], [max(times)]
g["buffers"][0]["uri"] = head + "," + base64.b64encode(bytes(raw)).decode()
json.dump(g, open(sys.argv[2], "w"))
PY
for f in 0 0.25 0.5; do
  "$cli" render --scene "$out/late.gltf" --path orbit-in --path-at $f \
    --technique uniform --size 96x54 --out "$out/at-$f.png" >/dev/null 2>"$out/at-$f.stderr" ||
    { echo "FAIL: render --path-at $f: $(cat "$out/at-$f.stderr")"; fail=1; }
done
check "--path-at 0 and 0.25 differ" bash -c "! cmp -s '$out/at-0.png' '$out/at-0.25.png'"
check "--path-at 0.25 and 0.5 differ" bash -c "! cmp -s '$out/at-0.25.png' '$out/at-0.5.png'"
exit $fail
