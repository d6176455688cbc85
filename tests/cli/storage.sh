#!/usr/bin/env bash
# shadowlab-cli storage (issue 10): the storage factor of Lloyd et al. 2006. The CSV's numbers
# against the paper's closed forms (overhead light: eq. 12 S = (f/n - 1) / (2 tan theta) for
# eta >= 0, the uniform map's (f/n - 1) f / (2 n tan theta) at eta = -1), the printed S,
# both PNGs written and not blank, bad values refused with exit 2; tsm's printed eta given to
# lispsm as --eta prints tsm's S (a TSM is one warp).
set -uo pipefail
cli=$1 out=$3/storage
rm -rf "$out"
mkdir -p "$out"
fail=0
"$cli" storage --near 1 --far 100 --fov 60 --grid 21 --csv "$out/s.csv" --out "$out/fig" \
  >"$out/stdout.txt" 2>"$out/stderr.txt" || { echo "FAIL: storage exited $?"; cat "$out/stderr.txt"; exit 1; }
cat "$out/stdout.txt"
# The printed S for the overhead light with LiSPSM: 99 / (2 tan 30 deg) = 85.7365.
grep -q '^S = 85.7365  M_x = 10  M_z = 8.57365' "$out/stdout.txt" || { echo "FAIL: printed S"; fail=1; }
python3 - "$out/s.csv" <<'PY' || fail=1
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
t = math.tan(math.radians(30)); n, f = 1.0, 100.0
eta = {round(float(r["eta"]), 4): r for r in rows if r["plot"] == "eta"}
bad = 0
def check(what, got, want):
    global bad
    ok = abs(got - want) <= 1e-5 * abs(want)
    print(("ok  " if ok else "FAIL") + f" {what}: {got:.6g} (closed form {want:.6g})")
    bad |= not ok
check("S at eta 0.5 (eq. 12, minimal)", float(eta[0.5]["s"]), (f / n - 1) / (2 * t))
check("S at eta -1 (uniform)", float(eta[-1.0]["s"]), (f / n - 1) * f / (2 * n * t))
# eta = -0.5: n' from eq. 11, S from eq. 12's second branch.
a = f / n; npr = n * (math.sqrt(a) + 1 + 0.5 * (a - 1)) / 0.5
check("S at eta -0.5 (eq. 11 + 12)", float(eta[-0.5]["s"]), (f / n - 1) / (2 * t) * f * npr**2 / (n * (npr + f - n)**2))
check("M_x at eta 1 (eq. 9, PSM)", float(eta[1.0]["mx"]), 1.0)
hemi = [r for r in rows if r["plot"] == "hemisphere"]
schemes = sorted({r["scheme"] for r in hemi})
print("hemisphere schemes:", schemes)
if len(schemes) != 8 or len(hemi) < 8 * 300: print("FAIL: hemisphere rows"); bad = 1
sys.exit(bad)
PY
python3 - "$out/fig-eta.png" "$out/fig-hemisphere.png" <<'PY' || fail=1
import sys, zlib, struct
# Not blank: a PNG with many distinct colours (decoded without third-party modules).
def colours(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, w, h, ctype = 8, b"", 0, 0, 0
    while pos < len(data):
        ln, tag = struct.unpack(">I4s", data[pos:pos + 8]); body = data[pos + 8:pos + 8 + ln]
        if tag == b"IHDR": w, h, _, ctype = struct.unpack(">IIBB", body[:10])
        if tag == b"IDAT": idat += body
        pos += 12 + ln
    bpp = {6: 4, 2: 3}[ctype]; raw = zlib.decompress(idat); stride = w * bpp
    seen, prev = set(), bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]; line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0; b = prev[i]; c = prev[i - bpp] if i >= bpp else 0
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            line[i] = (line[i] + [0, a, b, (a + b) // 2, pr][f]) & 255
        if y % 4 == 0:
            for x in range(0, w, 4): seen.add(bytes(line[x * bpp:x * bpp + 3]))
        prev = line
    return w, h, len(seen)
bad = 0
for path, want in zip(sys.argv[1:], (20, 200)):
    w, h, n = colours(path)
    print(f"{path}: {w}x{h}, {n} colours")
    if n < want: print(f"FAIL: {path} looks blank ({n} colours)"); bad = 1
sys.exit(bad)
PY
# TSM is one warp (Lloyd et al. §4.3): the eta --scheme tsm prints for its focus, given to
# lispsm as --eta, prints the same S, M_x, M_z (within 1e-5: the eta is printed to 6 digits).
# Light 30 deg to the right of behind, 40 up; focus 0.3 and 0.5 (the default).
for focus in 0.3 0.5; do
  "$cli" storage --near 1 --far 100 --fov 60 --light 30,40 --scheme tsm --focus "$focus" \
    >"$out/tsm.txt" || { echo "FAIL: storage --scheme tsm exited $?"; fail=1; }
  eta=$(awk '$1 == "whole" { for (i = 1; i < NF; ++i) if ($i == "eta") print $(i + 1) }' "$out/tsm.txt")
  "$cli" storage --near 1 --far 100 --fov 60 --light 30,40 --scheme lispsm --eta "$eta" \
    >"$out/eta.txt" || { echo "FAIL: storage --eta $eta exited $?"; fail=1; }
  python3 - "$out/tsm.txt" "$out/eta.txt" "$eta" "$focus" <<'PY' || fail=1
import re, sys
def sline(path):
    for line in open(path):
        m = re.match(r"S = (\S+)  M_x = (\S+)  M_z = (\S+)", line)
        if m: return [float(x) for x in m.groups()]
    raise SystemExit(f"FAIL: no S line in {path}")
t, e, eta = sline(sys.argv[1]), sline(sys.argv[2]), float(sys.argv[3])
ok = -1 < eta < 1 and all(abs(a - b) <= 1e-5 * abs(a) for a, b in zip(t, e))
print(("ok  " if ok else "FAIL") + f" tsm focus {sys.argv[4]}: eta {eta}, S M_x M_z {t}; one warp at that eta: {e}")
# The scheme asked for is named with its eta ("scheme eta" named the analysis' internals).
head = open(sys.argv[2]).readline()
named = f"scheme lispsm with eta {sys.argv[3]}," in head
print(("ok  " if named else "FAIL") + f" --scheme lispsm --eta: {head.strip()}")
sys.exit(0 if ok and named else 1)
PY
done
check() {
  local want=$1; shift
  local err rc=0
  err=$("$cli" storage "$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -ne 2 ] || [ "$err" != "$want" ]; then
    echo "FAIL (exit $rc): storage $* said '$err', expected '$want'"; fail=1
  else echo "ok: $err"; fi
}
check "shadowlab-cli: --far: 1 must be greater than --near (2)" --near 2 --far 1
check "shadowlab-cli: --far: 0.5 must be greater than --near (1, the default)" --far 0.5
check "shadowlab-cli: --near: 0 is out of range 1e-09..1e+12" --near 0
check "shadowlab-cli: --fov: 180 is out of range 1..170" --fov 180
check "shadowlab-cli: --scheme: unknown 'cube' (uniform, psm, lispsm, tsm, cascades, face)" --scheme cube
check "shadowlab-cli: --partitions: 9 is out of range 1..8" --scheme cascades --partitions 9
check "shadowlab-cli: --partitions: only cascades and face take partitions (got --scheme psm)" --scheme psm --partitions 2
check "shadowlab-cli: --eta: only psm and lispsm take an eta (got --scheme tsm: its eta follows from --focus, and is printed)" --scheme tsm --eta 0.5
check "shadowlab-cli: --focus: only tsm takes a focus (got --scheme lispsm)" --scheme lispsm --focus 0.5
check "shadowlab-cli: --eta: 2 is out of range -1..1" --eta 2
check "shadowlab-cli: --light: elevation must be in 0..90 degrees (the hemisphere above the viewer), got -10" --light 0,-10
check "shadowlab-cli: --out: '$out/x-eta.png' is the same file as --csv (one would overwrite the other)" --csv "$out/x-eta.png" --out "$out/x"
exit $fail
