#!/usr/bin/env bash
# What students and lecturers read cites papers by author and year, never by the project's
# seed numbers ("seed 004") or C++ symbols ("sl::rtw::momentsFromTop"): the lesson texts, and
# every string literal of the techniques, the renderer's declarations and the UI (parameter
# help, technique descriptions, pass explanations, tooltips). Comments are not scanned, nor
# the translation contexts of QCoreApplication::translate ("sl::ui::MainWindow"), nor a Qt style
# sheet's subcontrols ("QCheckBox::indicator").
# usage: lesson_texts_cite_authors.sh <repository root>
set -euo pipefail
root=$1
shopt -s nullglob
lessons=("$root"/scenes/lessons/*.json)
(( ${#lessons[@]} >= 10 )) || { echo "FAIL: only ${#lessons[@]} lessons found"; exit 1; }
fail=0
for f in "${lessons[@]}"; do
  if hits=$(grep -oE '.{0,30}([Ss]eed [0-9]{3}|[A-Za-z_]+::[A-Za-z_]+).{0,20}' "$f"); then
    echo "FAIL: $(basename "$f"): $hits"
    fail=1
  fi
done
(( fail == 0 )) && echo "PASS: ${#lessons[@]} lessons cite authors, no seed numbers or C++ symbols"
python3 - "$root" <<'PY' || fail=1
import pathlib, re, sys
root = pathlib.Path(sys.argv[1])
# (A Qt style sheet's subcontrol, "QCheckBox::indicator", is not a C++ symbol.)
bad = re.compile(r"seed [0-9]{3}|\b(?!Q[A-Z][A-Za-z]*::(?:indicator|item|handle|tab|pane|title|groove|chunk|branch|drop-down)\b)[A-Za-z_]+::[A-Za-z_]+")
literal = re.compile(r'"((?:[^"\\\n]|\\.)*)"')
context = re.compile(r'translate\(\s*"[^"]*"')
files = 0
hits = []
for folder in ("renderer/techniques", "renderer/core", "ui"):
    for f in sorted((root / folder).rglob("*")):
        if f.suffix not in (".cpp", ".h"):
            continue
        files += 1
        for n, line in enumerate(f.read_text(errors="replace").splitlines(), 1):
            if line.lstrip().startswith("//"):
                continue
            line = context.sub("translate(", line)
            for m in literal.finditer(line):
                if bad.search(m.group(1)):
                    hits.append(f"{f.relative_to(root)}:{n}: \"{m.group(1)[:90]}\"")
if files < 50:
    print(f"FAIL: only {files} source files scanned")
    sys.exit(1)
for h in hits:
    print("FAIL:", h)
if hits:
    sys.exit(1)
print(f"PASS: {files} source files: no seed numbers or C++ symbols in user-facing strings")
PY
exit $fail
