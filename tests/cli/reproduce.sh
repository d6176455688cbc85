#!/usr/bin/env bash
# shadowlab-cli reproduce --quick: every claim of scenes/claims/ measured at its small size.
# The report's structure: at least 25 claims from all five papers, each with its kind, the
# paper's quote (seed claims) or ShadowLab's statement (tool, check), its number, a measurement
# (or why not), a verdict of the five (marked indicative in a quick run), a threshold and the
# commands that re-run it; the headline counts seed claims per seed; report.json agrees with
# REPORT.md and every figure it names exists. Bad claims files: exit 2, one line naming the file
# and the JSON path; a claim that could not be measured exits 1; the report's commands are
# shell-quoted (a pasted command runs nothing else).
set -uo pipefail
cli=$1 out=$3/reproduce
rm -rf "$out"
mkdir -p "$out"
fail=0
rc=0
timeout 600 "$cli" reproduce --quick --out "$out/q" >"$out/stdout.txt" 2>"$out/stderr.txt" || rc=$?
# Exit 1 exactly when a claim could not be measured (0 otherwise).
want=0
grep -q '"verdict": "not testable here"' "$out/q/report.json" 2>/dev/null && want=1
if [ $rc -ne $want ]; then
  echo "FAIL: reproduce --quick exited $rc, expected $want"; tail -5 "$out/stderr.txt"; exit 1
fi
tail -1 "$out/stdout.txt"
python3 - "$out/q" <<'PY' || fail=1
import json, os, re, sys
d = sys.argv[1]
md = open(os.path.join(d, "REPORT.md"), encoding="utf-8").read()
rep = json.load(open(os.path.join(d, "report.json"), encoding="utf-8"))
bad = []
sections = re.split(r"^### ", md, flags=re.M)[1:]
ids = [s.split("\n", 1)[0].strip() for s in sections]
if len(ids) < 25: bad.append(f"{len(ids)} claims in REPORT.md, expected at least 25")
if ids != [e["id"] for e in rep]: bad.append("REPORT.md and report.json list different claims")
seeds = {e["seed"] for e in rep}
if seeds != {"000", "001", "002", "003", "004"}: bad.append(f"seeds {sorted(seeds)}, expected all five")
verdicts = {"reproduced", "partly", "not reproduced", "inconclusive", "not testable here"}
if "A quick run" not in md: bad.append("a quick run's report does not say so")
if "## Seed claims per seed" not in md or "## Threats to validity" not in md: bad.append("no per-seed headline or threats to validity")
for s, e in zip(sections, rep):
    cid = e["id"]
    fields = ["**Kind:** ", "**Paper's number:** ", "**Measurement (", "**Threshold:** ", "**Verdict:** ", "**Command:**"]
    fields.append("**Paper:** \"" if e["kind"] == "seed" else "**ShadowLab's claim:** " if e["kind"] == "tool" else "**Check:** ")
    for field in fields:
        if field not in s: bad.append(f"{cid}: no {field.strip()}")
    m = re.search(r"^\*\*Verdict:\*\* (.+?)( \(quick run: indicative\))?$", s, flags=re.M)
    if not m or m.group(1) not in verdicts: bad.append(f"{cid}: verdict {m.group(1) if m else None}")
    elif m.group(1) != e["verdict"]: bad.append(f"{cid}: verdicts differ")
    elif bool(m.group(2)) != e["indicative"]: bad.append(f"{cid}: indicative differs")
    words = e.get("quote", "") if e["kind"] == "seed" else e.get("statement", "")
    if not words.strip() or not e["paper_number"].strip(): bad.append(f"{cid}: no quote/statement or number")
    if not e["commands"] or not any(c.startswith("shadowlab-cli ") for c in e["commands"]): bad.append(f"{cid}: no command")
    if e["verdict"] == "not testable here":
        if e["measured"] or not e["measurement"]: bad.append(f"{cid}: not measured without a reason")
    elif not e["measured"] or "value" not in e: bad.append(f"{cid}: a verdict without a value")
    if e["verdict"] in ("not reproduced", "partly") and "**Mechanism:** " not in s: bad.append(f"{cid}: no mechanism line")
    for f in e["figures"]:
        p = os.path.join(d, f)
        if not os.path.isfile(p) or os.path.getsize(p) < 1000: bad.append(f"{cid}: figure {f} missing")
        if f"]({f})" not in s: bad.append(f"{cid}: figure {f} not in REPORT.md")
print("\n".join("FAIL: " + b for b in bad) if bad else f"ok: {len(ids)} claims, seeds {sorted(seeds)}, every claim with its kind, words, number, measurement, verdict, command")
sys.exit(1 if bad else 0)
PY

# --claim runs one claim; its command line is the report's.
"$cli" reproduce --quick --claim lloyd-storage-factor-minimal --out "$out/one" >/dev/null 2>&1 \
  && grep -q '^### lloyd-storage-factor-minimal' "$out/one/REPORT.md" \
  && [ "$(grep -c '^### ' "$out/one/REPORT.md")" = 1 ] || { echo "FAIL: --claim"; fail=1; }

# Bad input: one line, exit 2, naming the file and the JSON path.
bad() {  # name, expected text, json
  printf '%s' "$3" >"$out/$1.json"
  "$cli" reproduce --quick --claims "$out/$1.json" --out "$out/bad" >/dev/null 2>"$out/$1.err"
  local rc=$?
  if [ $rc -ne 2 ] || [ "$(wc -l <"$out/$1.err")" -ne 1 ] || ! grep -qF -- "$2" "$out/$1.err"; then
    echo "FAIL: $1: exit $rc, expected 2 and one line with '$2':"; cat "$out/$1.err"; fail=1
  else
    echo "ok: $1: $(cat "$out/$1.err")"
  fi
}
head='{"seed": "004", "source": "t", "claims": [{"id": "x", "kind": "tool", "statement": "w", "paper_number": "1", '
cpu='"measure": {"kind": "cpu", "storage": ["--scheme", "lispsm"], "value": "s"}'
bad op "op.json: claims[0].expect.op: expected" "$head$cpu, \"expect\": {\"op\": \"=~\", \"value\": 1}}]}"
bad key "key.json: claims[0].measure.colour: unknown key" "$head\"measure\": {\"kind\": \"cpu\", \"colour\": 1}, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
bad kind "kind.json: claims[0].measure.kind: unknown 'speed'" "$head\"measure\": {\"kind\": \"speed\"}, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
bad param "claims[0].measure.a: technique 'uniform' has no parameter 'resolutoin'" "$head\"measure\": {\"kind\": \"error-compare\", \"scene\": \"default\", \"a\": {\"technique\": \"uniform\", \"params\": {\"resolutoin\": \"1\"}}}, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
bad storage "claims[0].measure.storage: --scheme: unknown 'fast'" "$head\"measure\": {\"kind\": \"cpu\", \"storage\": [\"--scheme\", \"fast\"], \"value\": \"s\"}, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
bad json "not valid JSON" "$head"
seedhead='{"seed": "004", "source": "t", "claims": [{"id": "x", "kind": "seed", "paper_number": "1", '
bad seedquote "claims[0].quote: missing" "$seedhead$cpu, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
bad claimkind "claims[0].kind: expected seed" "${head/tool/paper}$cpu, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
ec='"measure": {"kind": "error-compare", "scene": "plane-box", "a": {"technique": "uniform"}, "b": {"technique": "uniform", "params": {"resolution": "512"}}'
bad noeffect "claims[0].partly: partly (<= 1.1) admits no effect (1)" "$head$ec}, \"expect\": {\"op\": \"<=\", \"value\": 1}, \"partly\": {\"op\": \"<=\", \"value\": 1.1}}]}"
bad fewframes "claims[0].measure.full: frames: 5, a error-compare needs at least 20" "$head$ec, \"full\": {\"frames\": 5}}, \"expect\": {\"op\": \"<=\", \"value\": 1}}]}"
bad camera "claims[0].measure.camera: missing (a publication is measured from a still camera)" "$head\"measure\": {\"kind\": \"publication\", \"scene\": \"diagonal\", \"a\": {\"technique\": \"da-rtw\"}, \"number\": \"rotation.deg\", \"statistic\": \"max\"}, \"expect\": {\"op\": \"<\", \"value\": 1}}]}"
# Claims that could not be measured (a pass no technique times; an error and an aliasing "< 1"
# from a camera that sees only sky, hostile fixture sky-view.gltf: they were "reproduced" with
# 0) and a scene name that is a command: exit 1, "not measured", and the report's commands quoted.
cat >"$out/unmeasured.json" <<'JSON'
{"seed": "004", "source": "t", "claims": [
 {"id": "no-pass", "kind": "tool", "statement": "w", "paper_number": "1",
  "measure": {"kind": "time-ratio", "scene": "plane-box", "metric": "pass:nothing",
              "a": {"technique": "uniform"}, "b": {"technique": "uniform", "params": {"resolution": "512"}},
              "quick": {"size": "64x36", "frames": 2, "warmup": 0}},
  "expect": {"op": "<", "value": 1}},
 {"id": "quoted", "kind": "tool", "statement": "w", "paper_number": "1",
  "measure": {"kind": "error-compare", "scene": "`touch INJECTED`x",
              "a": {"technique": "uniform"}, "quick": {"size": "64x36", "frames": 2, "warmup": 0}},
  "expect": {"op": "<", "value": 1}},
 {"id": "sky-error", "kind": "tool", "statement": "w", "paper_number": "1",
  "measure": {"kind": "error-compare", "scene": "SKY", "camera": "eye",
              "a": {"technique": "uniform"}, "quick": {"size": "64x36", "frames": 2, "warmup": 0}},
  "expect": {"op": "<", "value": 1}},
 {"id": "sky-aliasing", "kind": "tool", "statement": "w", "paper_number": "1",
  "measure": {"kind": "error-compare", "scene": "SKY", "camera": "eye", "metric": "aliasing_p95",
              "a": {"technique": "uniform"}, "quick": {"size": "64x36", "frames": 2, "warmup": 0}},
  "expect": {"op": "<", "value": 1}}]}
JSON
sky=$(cd "$(dirname "$0")/../fixtures/hostile" && pwd)/sky-view.gltf
sed -i "s|\"SKY\"|\"$sky\"|" "$out/unmeasured.json"
rc=0
"$cli" reproduce --quick --claims "$out/unmeasured.json" --out "$out/unmeasured" >/dev/null 2>&1 || rc=$?
[ $rc -eq 1 ] || { echo "FAIL: a claim not measured: exit $rc, expected 1"; fail=1; }
mkdir -p "$out/paste"
python3 - "$out/unmeasured/report.json" "$out/paste" <<'PY' || fail=1
import json, os, subprocess, sys
rep, sandbox = json.load(open(sys.argv[1])), sys.argv[2]
assert [e["verdict"] for e in rep] == ["not testable here"] * 4, [e["verdict"] for e in rep]
for e in rep[2:]:
    assert "not measured (no covered pixel)" in json.dumps(e), e
scene = "`touch INJECTED`x"
for e in rep:
    for cmd in e["commands"]:
        assert cmd.startswith("shadowlab-cli "), cmd
        # Pasted into a shell: the words it gives, and nothing run.
        words = subprocess.run(["bash", "-c", "printf '%s\n' " + cmd[len("shadowlab-cli "):]],
                               cwd=sandbox, capture_output=True, text=True).stdout.splitlines()
        if e["id"] == "quoted" and "--scene" in words:
            assert words[words.index("--scene") + 1] == scene, words
assert not os.listdir(sandbox), f"a pasted command ran: {os.listdir(sandbox)}"
print("ok: not testable here exits 1; pasted commands give the claim's words and run nothing")
PY
"$cli" reproduce --seed 005 --out "$out/bad" >/dev/null 2>"$out/seed.err"
[ $? -eq 2 ] && grep -q -- '--seed: expected 000' "$out/seed.err" || { echo "FAIL: --seed 005"; fail=1; }
[ $fail -eq 0 ] && echo "ok: reproduce"
exit $fail
