#!/usr/bin/env bash
# scripts/gpu-check.sh --dry-run, run as it runs on a GPU machine: copied into a headless
# folder (FOLDER/gpu-check.sh, FOLDER/bin/shadowlab-cli and shadowlab-make-scenes,
# FOLDER/share/shadowlab/{shaders,scenes}) and finding its binaries from where it lies. The
# CSV and the Markdown must hold every DA-RTW pass, the poster's Table 1 rows, the five
# techniques with their ratios to uniform, the GL renderer and the timing method. Also: from
# the repository it finds build/ (--locate), and bad options and missing binaries exit 2 with
# one line.
set -euo pipefail
cli=$1 out=$3/gpu_check
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
make_scenes=$(cd "$(dirname "$cli")/.." && pwd)/scenes/shadowlab-make-scenes
[[ -x $make_scenes ]] || { echo "FAIL: no shadowlab-make-scenes beside $cli ($make_scenes)"; exit 1; }
rm -rf "$out"
mkdir -p "$out"

# Bad options and missing binaries: exit 2, one line.
expect_usage_error() {
  local what=$1 rc=0
  shift
  "$@" >"$out/err.stdout" 2>"$out/err.stderr" || rc=$?
  [[ $rc == 2 ]] || { echo "FAIL: $what: exit $rc, expected 2"; cat "$out/err.stderr"; exit 1; }
  [[ $(wc -l <"$out/err.stderr") == 1 ]] || { echo "FAIL: $what: not one line:"; cat "$out/err.stderr"; exit 1; }
  grep -qF -- "$what" "$out/err.stderr" || { echo "FAIL: stderr does not name '$what':"; cat "$out/err.stderr"; exit 1; }
}
expect_usage_error "--bogus" bash "$root/scripts/gpu-check.sh" --bogus
expect_usage_error "--frames" bash "$root/scripts/gpu-check.sh" --frames 0
expect_usage_error "/nonexistent/shadowlab-cli" bash "$root/scripts/gpu-check.sh" \
  --cli /nonexistent/shadowlab-cli --make-scenes "$make_scenes" --out "$out/none"
[[ ! -e $out/none/gpu-check.md ]] || { echo "FAIL: wrote a table without binaries"; exit 1; }

# From the repository: build/ beside scripts/ (when that is the build under test).
if [[ $(cd "$(dirname "$cli")" && pwd -P) == $(cd "$root" && pwd -P)/build/app ]]; then
  bash "$root/scripts/gpu-check.sh" --locate >"$out/locate.txt"
  grep -q "^layout: repository" "$out/locate.txt" || { echo "FAIL: repo layout"; cat "$out/locate.txt"; exit 1; }
fi

# The headless folder.
folder=$out/folder
mkdir -p "$folder/bin" "$folder/lib" "$folder/share/shadowlab"
folder=$(cd "$folder" && pwd -P)
unset SHADOWLAB_SHADER_DIR SHADOWLAB_SCENE_DIR  # the folder's own, as on a GPU machine
cp "$root/scripts/gpu-check.sh" "$folder/"
ln -s "$(cd "$(dirname "$cli")" && pwd)/$(basename "$cli")" "$folder/bin/shadowlab-cli"
ln -s "$make_scenes" "$folder/bin/shadowlab-make-scenes"
ln -s "$root/shaders" "$folder/share/shadowlab/shaders"
ln -s "$root/scenes" "$folder/share/shadowlab/scenes"
(cd "$out" && bash "$folder/gpu-check.sh" --locate) >"$out/locate-folder.txt"
if ! grep -q "^layout: headless folder" "$out/locate-folder.txt" ||
  ! grep -qF "shaders: $folder/share/shadowlab/shaders" "$out/locate-folder.txt"; then
  echo "FAIL: headless layout"
  cat "$out/locate-folder.txt"
  exit 1
fi

start=$(date +%s)
(cd "$out" && bash "$folder/gpu-check.sh" --dry-run --out result) 2>"$out/run.stderr" ||
  { echo "FAIL: the dry run failed:"; cat "$out/run.stderr"; exit 1; }
echo "dry run: $(($(date +%s) - start)) s"
csv=$out/result/gpu-check.csv md=$out/result/gpu-check.md
[[ -s $csv && -s $md ]] || { echo "FAIL: no CSV or Markdown in $out/result"; exit 1; }
[[ -z $(find "$out/result" -maxdepth 1 -name '.gpu-check.*') ]] || { echo "FAIL: temp files left"; exit 1; }

python3 - "$csv" "$md" "$out/result/raw/da-rtw.json" <<'PY'
import csv, json, sys
csv_path, md_path, json_path = sys.argv[1:]
rows = list(csv.DictReader(open(csv_path)))
md = open(md_path).read()
metrics = json.load(open(json_path))
passes = [p["name"] for p in metrics["passes"]]
# Every DA-RTW pass the renderer timed, in the CSV and in the Markdown.
for name in ["rotation estimate", "focus", "importance", "moments", "blur", "scan + warp",
             "warped shadow map"]:
    assert name in passes, f"the metrics have no '{name}' pass: {passes}"
got = [r["name"] for r in rows if r["table"] == "da-rtw pass"]
assert got == passes, f"CSV passes {got} != metrics passes {passes}"
for name in passes:
    assert f"| {name} |" in md, f"Markdown has no row for pass '{name}'"
    row = next(r for r in rows if r["table"] == "da-rtw pass" and r["name"] == name)
    assert float(row["ms"]) >= 0, row
# The poster's Table 1 beside ours.
t1 = {r["name"]: r for r in rows if r["table"] == "da-rtw table 1"}
for name, poster in [("Rotation matrix estimation & light view frustum rotation", "0.12"),
                     ("IM generation", "0.70"), ("RTWSM creation", "1.24"),
                     ("Total shadow mapping", "2.06")]:
    assert t1[name]["poster_ms"] == poster, t1.get(name)
    assert name in md and poster in md, f"Markdown lacks Table 1 row {name} {poster}"
total = float(t1["Total shadow mapping"]["ms"])
parts = sum(float(t1[n]["ms"]) for n in ["Rotation matrix estimation & light view frustum rotation",
                                         "IM generation", "RTWSM creation"])
assert abs(total - parts) < 0.01, (total, parts)
# Five techniques, uniform's ratio 1.
frame = {r["name"]: r for r in rows if r["table"] == "whole frame"}
assert list(frame) == ["uniform", "rtw-backward", "da-rtw", "fvsm", "rmsm"], list(frame)
for t, r in frame.items():
    assert float(r["ms"]) > 0 and float(r["ratio_to_uniform"]) > 0, r
    assert f"| {t} |" in md, f"Markdown has no row for {t}"
assert frame["uniform"]["ratio_to_uniform"] == "1.00", frame["uniform"]
# GL strings and the timing method, stated.
for r in rows:
    assert r["gl_renderer"].strip() and r["gl_version"].strip(), r
    assert r["timing_method"] in ("glFinish+wallclock", "GL_TIME_ELAPSED"), r
    assert (r["width"], r["height"]) == ("320", "180"), r
assert metrics["gl_renderer"] and metrics["gl_vendor"] and metrics["gl_version"], metrics
assert f"| GL renderer | {metrics['gl_renderer']} |" in md
assert f"| timing method | {metrics['timing_method']}" in md
assert "dry run" in md and "| machine |" in md and "| date |" in md and "| command |" in md
triangles = int(rows[0]["triangles"])
assert 15000 <= triangles <= 20000, f"dry-run scene has {triangles} triangles"
print(f"ok: {len(passes)} passes, 5 techniques, {triangles} triangles, "
      f"{metrics['gl_renderer']}, timing {metrics['timing_method']}")
PY
