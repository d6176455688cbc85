#!/usr/bin/env bash
# shadowlab-cli render --path/--path-at renders the camera a bench frame uses (bench's frame f of
# F is the path at f / (F - 1)), and --publish adds a technique's curve to the metrics; bad
# values are refused with exit 2 and a message naming the option.
set -euo pipefail
cli=$1 out=$3/render_path_publish
mkdir -p "$out"
small=(--technique uniform --set resolution=512 --size 160x90)
"$cli" render --scene diagonal --path walk-along-row --path-at 0 "${small[@]}" \
  --out "$out/start.png" --metrics "$out/start.json" >/dev/null
"$cli" render --scene diagonal --path walk-along-row --path-at 1 "${small[@]}" \
  --out "$out/end.png" --metrics "$out/end.json" >/dev/null
"$cli" bench --scene diagonal --path walk-along-row --frames 2 --warmup 0 \
  --technique uniform:resolution=512 --size 160x90 --csv "$out/bench.csv" >/dev/null 2>&1
"$cli" render --scene diagonal --technique fvsm --set fvsm.max_texture=256 \
  --set fvsm.fallback.resolution=64 --size 160x90 --out "$out/fvsm.png" \
  --metrics "$out/fvsm.json" --publish fvsm.tiles.list --publish fvsm.tile_ms >/dev/null
python3 - "$out" <<'PY'
import csv, json, sys
d = sys.argv[1]
start, end = (json.load(open(f"{d}/{n}.json")) for n in ("start", "end"))
assert open(f"{d}/start.png", "rb").read() != open(f"{d}/end.png", "rb").read(), \
    "the path's start and end render the same image"
# bench's two frames are the path's start and end: its median is their mean.
row = next(csv.DictReader(open(f"{d}/bench.csv")))
mean = (start["error_pct"] + end["error_pct"]) / 2
assert abs(float(row["error_pct"]) - mean) <= 1e-5 * mean, (row["error_pct"], mean)  # CSV: 6 digits
f = json.load(open(f"{d}/fvsm.json"))
curves = f["published_curves"]
assert set(curves) == {"fvsm.tiles.list", "fvsm.tile_ms"}, curves.keys()
leaves = f["published"]["fvsm.tiles"]
assert leaves >= 1 and len(curves["fvsm.tiles.list"]) == 17 * leaves, (leaves, len(curves["fvsm.tiles.list"]))
assert len(curves["fvsm.tile_ms"]) == 2 * leaves
print(f"ok: path start/end error {start['error_pct']:.4f} / {end['error_pct']:.4f} % "
      f"(bench median {float(row['error_pct']):.4f}); fvsm published {leaves:.0f} leaves")
PY
refused() {  # refused "<what the message must name>" args...
  local want=$1; shift
  local rc=0
  "$cli" render --scene diagonal "${small[@]}" --out "$out/bad.png" "$@" 2>"$out/err.txt" >/dev/null || rc=$?
  if [ "$rc" != 2 ] || ! grep -q -- "$want" "$out/err.txt"; then
    echo "FAIL: render $* gave rc $rc, wanted 2 naming '$want':"; cat "$out/err.txt"; exit 1
  fi
}
refused "--path-at" --path walk-along-row --path-at 1.5
refused "--path-at: needs --path" --path-at 0.5
refused "--path: give either" --path walk-along-row --camera row-end
refused "walk-along-row" --path no-such-path
refused "its curves: none" --publish fvsm.tiles.list
echo "ok: bad --path/--path-at/--publish refused"
