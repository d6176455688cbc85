#!/usr/bin/env bash
# Suites checked at load (issue 14): a case's scene that does not exist and a size this
# OpenGL implementation cannot render are refused (exit 2, naming the file and the JSON
# path) before any case runs; a technique whose frames cover no pixel reports its error as
# not measured (null in the JSON, "n/a" in the table) and its expectations on error metrics
# are skipped, not passed or failed on a made-up 0; a case that checks none of its
# expectations that way fails.
set -uo pipefail
cli=$1 out=$3/suite-load-checks
rm -rf "$out" && mkdir -p "$out"
cd "$out" || exit 1
fail=0
p="shadowlab-cli"

# expect_error RC WANT ARGS...: the exit code, and stderr's last line is WANT (a trailing '*'
# in WANT matches any rest); nothing ran: no case table on stdout, no case in the JSON.
expect_error() {
  local rc want=$2 want_rc=$1 last
  shift 2
  rm -f run.json
  last=$(timeout 60 "$cli" "$@" --json run.json 2>&1 >stdout.txt | tail -n 1)
  rc=${PIPESTATUS[0]}
  local matches=0
  if [[ "$want" == *'*' ]]; then [[ "$last" == "${want%'*'}"* ]] && matches=1
  elif [ "$last" == "$want" ]; then matches=1; fi
  [ "$rc" == "$want_rc" ] && [ $matches == 1 ] ||
    { printf 'FAIL: %s: exit %s, said\n  %s\nnot (exit %s)\n  %s\n' "$*" "$rc" "$last" "$want_rc" "$want"; fail=1; }
  grep -q '^== ' stdout.txt && { echo "FAIL: $*: a case ran"; fail=1; }
  [ ! -e run.json ] || python3 -c 'import json,sys; sys.exit(len(json.load(open("run.json"))["cases"]))' ||
    { echo "FAIL: $*: run.json holds a case"; fail=1; }
}

# suite NAME SIZE CASE2_SCENE CASE2_SIZE: a two-case suite; the second case is the one at fault.
suite() {
  cat >"$1" <<JSON
{"name": "load checks", "size": $2, "cases": [
  {"name": "fine", "scene": "plane-box", "frames": 2, "techniques": ["uniform"]},
  {"name": "second", "scene": "$3", "frames": 2, "size": $4, "techniques": ["uniform"]}]}
JSON
}

# A scene that does not exist: a built-in name or a path.
suite missing-scene.json '[64, 36]' no-such-scene '[64, 36]'
expect_error 2 "$p: missing-scene.json: cases[1].scene: unknown scene 'no-such-scene' (built-in scenes: *" \
  stability --suite missing-scene.json
suite missing-path.json '[64, 36]' nowhere/x.gltf '[64, 36]'
expect_error 2 "$p: missing-path.json: cases[1].scene: no file 'nowhere/x.gltf'" \
  stability --suite missing-path.json

# Sizes against the GL limits, in --size's words, naming where the size came from.
too_big="16384x16384 is larger than this OpenGL implementation allocates (a 16384x16384 RGBA32F G-buffer target is refused by GL_PROXY_TEXTURE_2D)"
suite big-case.json '[64, 36]' plane-box '[20000, 100]'
expect_error 2 "$p: big-case.json: cases[1].size: 20000x100 is wider than this OpenGL implementation renders (GL_MAX_TEXTURE_SIZE 16384)" \
  stability --suite big-case.json
suite big-suite.json '[16384, 16384]' plane-box '[64, 36]'
expect_error 2 "$p: big-suite.json: size: $too_big" stability --suite big-suite.json
suite fine.json '[64, 36]' plane-box '[64, 36]'
expect_error 2 "$p: --size: $too_big" stability --suite fine.json --size 16384x16384

# No covered pixel: a camera looking into the empty sky.
cat >sky.json <<'JSON'
{"name": "sky", "size": [64, 36], "cases": [
  {"name": "sky", "scene": "plane-box", "frames": 2,
   "camera": {"position": [0, 5, 0], "target": [0.01, 50, 0.01]},
   "techniques": ["uniform", {"id": "uniform", "label": "fine", "set": {"resolution": 4096}}],
   "expect": [
     {"technique": "uniform", "metric": "error_pct", "op": "<", "value": 1},
     {"technique": "*", "metric": "false_lit_pct", "op": "==", "value": 0},
     {"better": "fine", "worse": "uniform", "metric": "error_pct"},
     {"technique": "uniform", "metric": "covered_pixels", "op": "==", "value": 0}]}]}
JSON
if timeout 120 "$cli" stability --suite sky.json --json sky.out.json >sky.stdout 2>sky.stderr; then
  want="   skipped: uniform error_pct < 1: not measured (no covered pixel)
   skipped: * false_lit_pct == 0: not measured (no covered pixel)
   skipped: fine error_pct < uniform error_pct: not measured (no covered pixel)
   pass: uniform covered_pixels == 0 (got 0)"
  got=$(grep -E '^   (skipped|pass|FAIL)' sky.stdout)
  if [ "$got" != "$want" ]; then
    printf 'FAIL: sky expectations:\n%s\nexpected:\n%s\n' "$got" "$want"; fail=1
  fi
  if ! grep -qE '^   uniform +n/a ' sky.stdout; then
    echo "FAIL: sky table does not say n/a:"; grep '^   uniform' sky.stdout; fail=1
  fi
  got=$(python3 - <<'PY'
import json
j = json.load(open("sky.out.json"))
t = j["cases"][0]["techniques"]["uniform"]
print(t["error_pct"], t["false_lit_pct"], t["false_shadow_pct"], t["covered_pixels"],
      [e["status"] for e in j["cases"][0]["expectations"]], j["passed"], j["skipped"], j["failed"])
PY
)
  want="None None None 0 ['skipped', 'skipped', 'skipped', 'pass'] 1 3 0"
  [ "$got" == "$want" ] || { printf 'FAIL: sky JSON: %s\nexpected: %s\n' "$got" "$want"; fail=1; }
else
  echo "FAIL: stability --suite sky.json exited $?:"; cat sky.stderr; fail=1
fi

# Frames with covered pixels still measure (a number, not null).
if timeout 120 "$cli" stability --suite fine.json --json fine.out.json >/dev/null 2>fine.stderr; then
  got=$(python3 -c 'import json; print(type(json.load(open("fine.out.json"))["cases"][0]["techniques"]["uniform"]["error_pct"]).__name__)')
  [[ "$got" == int || "$got" == float ]] || { echo "FAIL: fine error_pct is $got"; fail=1; }
else
  echo "FAIL: stability --suite fine.json:"; cat fine.stderr; fail=1
fi

# A case whose every expectation goes unchecked for want of covered pixels checked nothing:
# it fails (exit 1, naming the case) instead of passing by accident.
cat >sky-only.json <<'JSON'
{"name": "sky only", "size": [64, 36], "cases": [
  {"name": "sky-only", "scene": "plane-box", "frames": 1,
   "camera": {"position": [0, 5, 0], "target": [0.01, 50, 0.01]},
   "techniques": ["uniform"],
   "expect": [{"technique": "uniform", "metric": "error_pct", "op": "<", "value": 1}]}]}
JSON
timeout 120 "$cli" stability --suite sky-only.json --json sky-only.out.json >sky-only.stdout 2>sky-only.stderr
rc=$?
want="shadowlab-cli: FAILED case 'sky-only': the case checks at least one of its expectations (checked none: 1 of 1 not measured (no covered pixel))"
if [ $rc -ne 1 ] || ! grep -qxF "$want" sky-only.stderr; then
  printf 'FAIL: sky-only exited %s (want 1) and stderr:\n' "$rc"; cat sky-only.stderr; fail=1
fi
got=$(python3 -c 'import json; j = json.load(open("sky-only.out.json")); print(j["passed"], j["skipped"], j["failed"])')
[ "$got" == "0 1 1" ] || { echo "FAIL: sky-only JSON passed/skipped/failed: $got (want 0 1 1)"; fail=1; }

[ $fail -eq 0 ] && echo "suite load checks: ok"
exit $fail
