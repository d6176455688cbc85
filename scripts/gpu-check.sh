#!/usr/bin/env bash
# The GPU check: on a generated Sponza-class atrium (~262 k triangles, as the Crytek Sponza of
# the DA-RTW poster's Table 1), DA-RTW's time per pass beside the poster's numbers, and the
# whole-frame time of uniform, rtw-backward, da-rtw, fvsm and rmsm, measured interleaved, with
# their ratios to uniform. Writes gpu-check.csv and gpu-check.md (and the raw outputs under
# raw/) into --out DIR. Runs from the repository (scripts/gpu-check.sh, build/ binaries) or
# from a headless folder (FOLDER/gpu-check.sh, FOLDER/bin, FOLDER/lib, FOLDER/share/shadowlab).
# See docs/results/gpu.md.
set -euo pipefail

self=gpu-check.sh
usage="usage: $self [--out DIR] [--dry-run] [--frames N] [--cli PATH] [--make-scenes PATH] [--locate]
  --out DIR           where gpu-check.csv, gpu-check.md and raw/ go (default gpu-check-out)
  --dry-run           small sizes (320x180, a 20 k-triangle scene, 3 frames): checks the
                      script on any GL, software included, in well under a minute
  --frames N          measured frames per configuration (medians; default 20, dry run 3)
  --cli PATH          shadowlab-cli to use (default: found from where this script lies)
  --make-scenes PATH  shadowlab-make-scenes to use (likewise)
  --locate            print the layout and the binaries it would use, and exit"

fail_usage() {
  echo "$self: $1" >&2
  exit 2
}

out=gpu-check-out dry_run=0 frames="" cli="" make_scenes="" locate=0
command_line="$self"
for arg in "$@"; do command_line+=" $(printf '%q' "$arg")"; done
while (($#)); do
  case $1 in
    --out | --frames | --cli | --make-scenes)
      if (($# < 2)) || [[ -z $2 ]]; then fail_usage "$1: missing its value (see --help)"; fi
      case $1 in
        --out) out=$2 ;;
        --frames) frames=$2 ;;
        --cli) cli=$2 ;;
        --make-scenes) make_scenes=$2 ;;
      esac
      shift 2
      ;;
    --dry-run) dry_run=1 && shift ;;
    --locate) locate=1 && shift ;;
    -h | --help) echo "$usage" && exit 0 ;;
    *) fail_usage "unknown option '$1' (see --help)" ;;
  esac
done
if [[ -n $frames ]] && ! [[ $frames =~ ^[1-9][0-9]{0,3}$ ]]; then
  fail_usage "--frames: expected a whole number 1..9999, got '$frames'"
fi

# --- Where the binaries are: the layout is read from where this script lies.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd -P)
if [[ -e $here/bin/shadowlab-cli ]]; then
  layout="headless folder $here"
  default_cli=$here/bin/shadowlab-cli default_make=$here/bin/shadowlab-make-scenes
  # The folder's shaders and built-in scenes, unless the environment names others; its
  # libraries first.
  share=$here/share/shadowlab
  if [[ -z ${SHADOWLAB_SHADER_DIR:-} && -d $share/shaders ]]; then
    export SHADOWLAB_SHADER_DIR=$share/shaders
  fi
  if [[ -z ${SHADOWLAB_SCENE_DIR:-} && -d $share/scenes ]]; then
    export SHADOWLAB_SCENE_DIR=$share/scenes
  fi
  if [[ -d $here/lib ]]; then export LD_LIBRARY_PATH=$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}; fi
elif [[ -f $here/../CMakeLists.txt && -d $here/../renderer ]]; then
  root=$(cd "$here/.." && pwd -P)
  layout="repository $root"
  default_cli=$root/build/app/shadowlab-cli default_make=$root/build/scenes/shadowlab-make-scenes
else
  layout="unknown (neither FOLDER/bin/shadowlab-cli nor a repository beside $here)"
  default_cli="" default_make=""
fi
cli=${cli:-$default_cli} make_scenes=${make_scenes:-$default_make}
[[ -n $cli ]] || fail_usage "no shadowlab-cli: layout $layout; give --cli PATH"
[[ -n $make_scenes ]] || fail_usage "no shadowlab-make-scenes: layout $layout; give --make-scenes PATH"
[[ -f $cli && -x $cli ]] || fail_usage "shadowlab-cli not found or not executable: $cli (give --cli PATH)"
[[ -f $make_scenes && -x $make_scenes ]] ||
  fail_usage "shadowlab-make-scenes not found or not executable: $make_scenes (give --make-scenes PATH)"
if ((locate)); then
  printf 'layout: %s\ncli: %s\nmake-scenes: %s\nshaders: %s\nscenes: %s\n' "$layout" "$cli" \
    "$make_scenes" "${SHADOWLAB_SHADER_DIR:-(compiled-in)}" "${SHADOWLAB_SCENE_DIR:-(compiled-in)}"
  exit 0
fi

# --- What to measure.
techniques=(uniform rtw-backward da-rtw fvsm rmsm)
if ((dry_run)); then
  size=320x180 shadow_map=512 triangles_arg=(--triangles 20000) warmup=2 frames=${frames:-3}
else
  size=1920x1080 shadow_map=2048 triangles_arg=() warmup=10 frames=${frames:-20}
fi
width=${size%x*} height=${size#*x}

# Every file this run writes, checked before the first step (the headless folder carries no
# scripts/lib, so the output policy's rules for a fixed set of names are spelt out here): an
# existing one must be a regular file (a link is followed), never a folder, FIFO, device or
# socket, which a rename would move into or a redirection would block on.
if [[ -e $out || -L $out ]] && [[ ! -d $out ]]; then fail_usage "--out '$out' is not a folder"; fi
if [[ -e $out/raw || -L $out/raw ]] && [[ ! -d $out/raw ]]; then
  fail_usage "--out: '$out/raw' exists and is not a folder"
fi
for f in gpu-check.csv gpu-check.md raw/make-scenes.log raw/da-rtw.log raw/bench.log \
  raw/da-rtw.png raw/da-rtw.json raw/bench.csv; do
  p=$out/$f
  if [[ -L $p && ! -e $p ]]; then fail_usage "--out: '$p' is a link to nothing"; fi
  if [[ -e $p && ! -f $p ]]; then
    if [[ -d $p ]]; then
      fail_usage "--out: '$p' is a folder, not a file this run can write"
    else
      fail_usage "--out: '$p' is not a regular file (a FIFO, device or socket)"
    fi
  fi
done
mkdir -p "$out/raw" 2>/dev/null || fail_usage "--out: cannot create $out/raw"
out=$(cd "$out" && pwd -P)
raw=$out/raw
scratch=$(mktemp -d "${TMPDIR:-/tmp}/gpu-check.XXXXXX")
csv_tmp=$out/.gpu-check.csv.$$ md_tmp=$out/.gpu-check.md.$$
trap 'rm -rf "$scratch" "$csv_tmp" "$md_tmp"' EXIT

# Runs one step with its output in raw/LOG; on failure one line naming it, the log's tail,
# exit 1.
step() {
  local what=$1 log=$raw/$2 rc=0
  shift 2
  echo "$self: $what ..." >&2
  "$@" >"$log" 2>&1 || rc=$?
  if ((rc != 0)); then
    echo "$self: $what failed (exit $rc); the end of $log:" >&2
    tail -n 5 "$log" | tr '\r' '\n' | tail -n 5 >&2
    exit 1
  fi
}

# --no-reference (skip the Embree reference: not needed for timings) where the CLI has it.
render_help=$("$cli" render --help 2>&1 || true)
bench_help=$("$cli" bench --help 2>&1 || true)
render_noref=() bench_noref=()
if [[ $render_help == *--no-reference* ]]; then render_noref=(--no-reference); fi
if [[ $bench_help == *--no-reference* ]]; then bench_noref=(--no-reference); fi
case ${#render_noref[@]}${#bench_noref[@]} in
  11) reference="skipped (--no-reference)" ;;
  00) reference="computed (this shadowlab-cli has no --no-reference; not needed for timings)" ;;
  10) reference="skipped by render (--no-reference), computed by bench (no --no-reference)" ;;
  *) reference="computed by render (no --no-reference), skipped by bench (--no-reference)" ;;
esac

started=$(date +%s)
scene=$scratch/sponza-class.glb
step "generating the atrium" make-scenes.log "$make_scenes" --sponza-class "$scene" "${triangles_arg[@]}"
triangles=$(sed -n '1s/^.*: \([0-9][0-9]*\) triangles,.*$/\1/p' "$raw/make-scenes.log")
[[ -n $triangles ]] || {
  echo "$self: no triangle count in $raw/make-scenes.log" >&2
  exit 1
}

# DA-RTW per pass: medians over the frames after render's own warm-up (until the rotation
# settles); the metrics also give the GL strings and the timing method.
step "da-rtw per pass ($size, ${shadow_map}², $frames frames)" da-rtw.log \
  "$cli" render --scene "$scene" --camera atrium --technique da-rtw --set resolution="$shadow_map" \
  --size "$size" --frames "$frames" "${render_noref[@]}" --out "$raw/da-rtw.png" \
  --metrics "$raw/da-rtw.json"

# Whole frames: bench interleaves the configurations frame by frame.
bench_techniques=()
for t in "${techniques[@]}"; do
  case $t in
    uniform | rtw-backward | da-rtw) bench_techniques+=(--technique "$t:resolution=$shadow_map") ;;
    *) bench_techniques+=(--technique "$t") ;;  # fvsm, rmsm: their own defaults
  esac
done
step "whole frames, interleaved (${techniques[*]})" bench.log \
  "$cli" bench --scene "$scene" --camera atrium "${bench_techniques[@]}" --size "$size" \
  --frames "$frames" --warmup "$warmup" "${bench_noref[@]}" --csv "$raw/bench.csv"
elapsed=$(($(date +%s) - started))

# --- The machine.
gpu_smi=""
if command -v nvidia-smi >/dev/null 2>&1; then
  gpu_smi=$(nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | head -n 1 || true)
fi
cpu_model=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1 || true)

# --- The tables: one awk program reads the metrics JSON (nlohmann's dump(2): one key a line)
# and the bench CSV, and writes the CSV and the Markdown. POSIX awk only: a GPU machine may
# have no Python.
# Values go in through the environment: awk -v would interpret backslashes in them.
GC_CSV=$csv_tmp GC_MD=$md_tmp GC_TECHNIQUES="${techniques[*]}" GC_WIDTH=$width GC_HEIGHT=$height \
  GC_SHADOW_MAP=$shadow_map GC_FRAMES=$frames GC_TRIANGLES=$triangles GC_DRY_RUN=$dry_run \
  GC_COMMAND=$command_line GC_DATE=$(date -u '+%Y-%m-%d %H:%M UTC') GC_HOST=$(uname -n) \
  GC_NPROC=$(nproc) GC_CPU=$cpu_model GC_SMI=$gpu_smi GC_LAYOUT=$layout GC_CLI=$cli \
  GC_ELAPSED=$elapsed GC_REFERENCE=$reference awk '
function unescape(s) {
  gsub(/\\"/, "\"", s); gsub(/\\\\/, "\\", s); return s
}
# The string or number value of a `"key": value,` line.
function value(line,   v) {
  v = line; sub(/^[^:]*: */, "", v); sub(/,$/, "", v)
  if (v ~ /^".*"$/) v = unescape(substr(v, 2, length(v) - 2))
  return v
}
function csvsplit(line, f,   n, i, c, q, cur) {
  n = 0; cur = ""; q = 0
  for (i = 1; i <= length(line); i++) {
    c = substr(line, i, 1)
    if (q) {
      if (c == "\"") { if (substr(line, i + 1, 1) == "\"") { cur = cur "\""; i++ } else q = 0 }
      else cur = cur c
    } else if (c == "\"") q = 1
    else if (c == ",") { f[++n] = cur; cur = "" }
    else cur = cur c
  }
  f[++n] = cur
  return n
}
function csvq(s) {
  if (s !~ /[",\n]/) return s
  gsub(/"/, "\"\"", s); return "\"" s "\""
}
function ms(x) { return x == "" ? "" : sprintf("%.3f", x) }
# Which row of the poster\047s Table 1 a DA-RTW pass counts towards (0: the camera\047s passes).
function table1_row(p) {
  if (p == "rotation estimate" || p == "moments" || p == "focus") return 1
  if (p == "importance") return 2
  if (p == "blur" || p == "scan + warp" || p == "warped shadow map" || p == "collapse") return 3
  return 0
}
function csv_row(table, name, params, v, poster, ratio, mib, method) {
  print csvq(table) "," csvq(name) "," csvq(params) "," ms(v) "," poster "," ratio "," mib "," \
    csvq(method) "," width "," \
    height "," shadow_map "," triangles "," frames "," csvq(gl_vendor) "," csvq(gl_renderer) "," \
    csvq(gl_version) > csv_out
}
BEGIN {
  csv_out = ENVIRON["GC_CSV"]; md_out = ENVIRON["GC_MD"]; techniques = ENVIRON["GC_TECHNIQUES"]
  width = ENVIRON["GC_WIDTH"]; height = ENVIRON["GC_HEIGHT"]; shadow_map = ENVIRON["GC_SHADOW_MAP"]
  frames = ENVIRON["GC_FRAMES"]; triangles = ENVIRON["GC_TRIANGLES"]; dry_run = ENVIRON["GC_DRY_RUN"]
  command_line = ENVIRON["GC_COMMAND"]; date_utc = ENVIRON["GC_DATE"]; host = ENVIRON["GC_HOST"]
  nproc = ENVIRON["GC_NPROC"]; cpu_model = ENVIRON["GC_CPU"]; gpu_smi = ENVIRON["GC_SMI"]
  layout = ENVIRON["GC_LAYOUT"]; cli = ENVIRON["GC_CLI"]; elapsed = ENVIRON["GC_ELAPSED"]
  reference = ENVIRON["GC_REFERENCE"]
  t1name[1] = "Rotation matrix estimation & light view frustum rotation"; t1ms[1] = "0.12"
  t1name[2] = "IM generation"; t1ms[2] = "0.70"
  t1name[3] = "RTWSM creation"; t1ms[3] = "1.24"
  t1tag[1] = "(a)+(b)"; t1tag[2] = "(c)"; t1tag[3] = "(d)"
}
FILENAME ~ /\.json$/ {
  if ($0 ~ /^  "passes": \[/) { in_passes = 1; next }
  if (in_passes) {
    if ($0 ~ /^  \]/) { in_passes = 0; next }
    if ($0 ~ /^ *"name": /) pname = value($0)
    if ($0 ~ /^ *"ms": /) pms = value($0)
    if ($0 ~ /^ *"method": /) pmethod = value($0)
    if ($0 ~ /^    }/) { npass++; pass[npass] = pname; passms[npass] = pms; method = pmethod }
    next
  }
  if ($0 ~ /^  "gl_vendor": /) gl_vendor = value($0)
  if ($0 ~ /^  "gl_renderer": /) gl_renderer = value($0)
  if ($0 ~ /^  "gl_version": /) gl_version = value($0)
  if ($0 ~ /^  "timing_method": /) method = value($0)
  if ($0 ~ /^  "warmup_frames": /) warmup_frames = value($0)
  if ($0 ~ /^  "total_ms": /) da_total = value($0)
  next
}
FNR == 1 { n = csvsplit($0, head); for (i = 1; i <= n; i++) col[head[i]] = i; next }
{
  csvsplit($0, f)
  bt = f[col["technique"]]; bench_ms[bt] = f[col["total_ms"]]; bench_params[bt] = f[col["params"]]
  bench_mib[bt] = f[col["bytes"]] == "" ? "" : sprintf("%.1f", f[col["bytes"]] / 1048576)
  bench_method[bt] = f[col["timing_method"]]; bench_frames = f[col["frames"]]
}
END {
  print "table,name,params,ms,poster_ms,ratio_to_uniform,shadow_mib,timing_method,width,height,shadow_map," \
    "triangles,frames,gl_vendor,gl_renderer,gl_version" > csv_out
  for (i = 1; i <= npass; i++) {
    r = table1_row(pass[i])
    csv_row("da-rtw pass", pass[i], "", passms[i], "", "", "", method)
    if (r) { t1sum[r] += passms[i]; t1passes[r] = t1passes[r] (t1passes[r] == "" ? "" : " + ") pass[i] }
  }
  for (r = 1; r <= 3; r++) { csv_row("da-rtw table 1", t1name[r], "", t1sum[r], t1ms[r], "", "", method); shadow += t1sum[r] }
  csv_row("da-rtw table 1", "Total shadow mapping", "", shadow, "2.06", "", "", method)
  csv_row("da-rtw table 1", "Whole frame", "", da_total, "", "", "", method)
  nt = split(techniques, tech, " ")
  base = bench_ms["uniform"]
  for (i = 1; i <= nt; i++) {
    t = tech[i]
    ratio[t] = (bench_ms[t] != "" && base > 0) ? sprintf("%.2f", bench_ms[t] / base) : ""
    csv_row("whole frame", t, bench_params[t], bench_ms[t], "", ratio[t], bench_mib[t], bench_method[t])
  }

  title = dry_run + 0 ? "ShadowLab GPU check: dry run (small sizes; not a measurement)" : "ShadowLab GPU check"
  print "# " title "\n" > md_out
  print "| what | value |" > md_out
  print "|---|---|" > md_out
  print "| date | " date_utc " |" > md_out
  print "| command | `" command_line "` |" > md_out
  print "| machine | " host ", " nproc " CPU threads" (cpu_model == "" ? "" : " (" cpu_model ")") " |" > md_out
  print "| GL vendor | " gl_vendor " |" > md_out
  print "| GL renderer | " gl_renderer " |" > md_out
  print "| GL version | " gl_version " |" > md_out
  if (gpu_smi != "") print "| nvidia-smi | " gpu_smi " |" > md_out
  print "| timing method | " method (method == "GL_TIME_ELAPSED" ? " (timer queries, GPU time)" : method ~ /glFinish/ ? " (software GL: glFinish and a wall clock per pass)" : "") " |" > md_out
  print "| scene | generated atrium (`shadowlab-make-scenes --sponza-class`), " triangles " triangles, camera `atrium` |" > md_out
  print "| frame | " width "x" height ", shadow map " shadow_map "² (uniform, rtw-backward, da-rtw; fvsm and rmsm at their defaults) |" > md_out
  print "| frames | medians over " frames " measured frame" (frames == 1 ? "" : "s") "; da-rtw after " warmup_frames " warm-up frame(s) until its rotation settled |" > md_out
  print "| Embree reference | " reference " |" > md_out
  print "| binaries | " layout ", `" cli "` |" > md_out
  print "| run time | " elapsed " s |\n" > md_out

  print "## DA-RTW per pass\n" > md_out
  print "The poster\047s Table 1 (Tokuyoshi et al. 2014): Crytek Sponza, 262 k triangles, GeForce GTX 780. Passes marked \"camera\" render the view and are not in it.\n" > md_out
  print "| pass | ms | Table 1 row |" > md_out
  print "|---|---:|---|" > md_out
  for (i = 1; i <= npass; i++) {
    r = table1_row(pass[i])
    print "| " pass[i] " | " ms(passms[i]) " | " (r ? t1tag[r] " " t1name[r] : "camera") " |" > md_out
  }
  print "| **whole frame** | **" ms(da_total) "** | |\n" > md_out
  print "| Table 1 row | passes here | ms here | Table 1 ms (GTX 780) |" > md_out
  print "|---|---|---:|---:|" > md_out
  for (r = 1; r <= 3; r++) print "| " t1tag[r] " " t1name[r] " | " t1passes[r] " | " ms(t1sum[r]) " | " t1ms[r] " |" > md_out
  print "| **Total shadow mapping** | | **" ms(shadow) "** | **2.06** |\n" > md_out

  print "## Whole frame per technique (interleaved)\n" > md_out
  print "`shadowlab-cli bench` renders the techniques in turn, frame by frame (" bench_frames " frame" (bench_frames == 1 ? "" : "s") ", medians), so drift hits all alike. A frame is every pass, the camera\047s included; MiB: the shadow maps\047 memory.\n" > md_out
  print "| technique | parameters | ms | ratio to uniform | MiB |" > md_out
  print "|---|---|---:|---:|---:|" > md_out
  for (i = 1; i <= nt; i++) {
    t = tech[i]
    print "| " t " | " (bench_params[t] == "" ? "defaults" : bench_params[t]) " | " ms(bench_ms[t]) " | " ratio[t] " | " bench_mib[t] " |" > md_out
  }
}
' "$raw/da-rtw.json" "$raw/bench.csv"
# -T: the name itself is replaced (a folder made since the check fails the move, never takes it).
mv -fT "$csv_tmp" "$out/gpu-check.csv"
mv -fT "$md_tmp" "$out/gpu-check.md"
echo "$self: wrote $out/gpu-check.csv and $out/gpu-check.md (raw outputs in $raw, $elapsed s)" >&2
