#!/usr/bin/env bash
# The documentation holds together: README.md is a front page of at most 200 lines; every
# Markdown page under docs/ is reachable from docs/index.md or README.md through relative
# links; every relative link and image in README.md and docs/**/*.md names a file that exists;
# and the docs speak of the product, not of the project's issues or work steps (the grep
# below finds nothing). One line per problem.
# usage: docs.sh <repository root>
set -euo pipefail
root=$1
fail=0

lines=$(wc -l <"$root/README.md")
if ((lines > 200)); then
  echo "FAIL: README.md has $lines lines (at most 200: move the rest into docs/)"
  fail=1
fi

# Project notes: issue and work-step numbers.
if hits=$(cd "$root" && grep -rniE 'issue [0-9]|this stop|stop [0-9]|issues? #?[0-9]' README.md docs/); then
  while IFS= read -r hit; do
    echo "FAIL: ${hit:0:200}: names an issue or a work step (write about the product)"
  done <<<"$hits"
  fail=1
fi

python3 - "$root" <<'PY' || fail=1
import pathlib, re, sys, urllib.parse
root = pathlib.Path(sys.argv[1]).resolve()
pages = sorted((root / "docs").rglob("*.md"))
if len(pages) < 10:
    print(f"FAIL: only {len(pages)} Markdown pages under docs/ (is the search broken?)")
    sys.exit(1)
files = [root / "README.md"] + pages

inline = re.compile(r"\]\(\s*<?([^()\s<>]+(?:\([^()\s]*\)[^()\s<>]*)*)>?(?:\s+\"[^\"]*\")?\s*\)")
reference = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+\"[^\"]*\")?\s*$")
code_span = re.compile(r"(`+).*?\1")

def links(path):
    """(line number, target) of every relative link or image outside code."""
    fence = None
    for n, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
        m = re.match(r"^\s{0,3}(`{3,}|~{3,})", line)
        if m:
            if fence is None:
                fence = m.group(1)[0] * 3
            elif m.group(1).startswith(fence):
                fence = None
            continue
        if fence is not None:
            continue
        text = code_span.sub("", line)
        targets = inline.findall(text)
        m = reference.match(text)
        if m:
            targets.append(m.group(1))
        for t in targets:
            if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", t) or t.startswith("#"):
                continue  # a URL (http:, mailto:...) or an anchor in the same page
            yield n, t

problems = 0
graph = {}
for f in files:
    rel = f.relative_to(root)
    graph[f] = set()
    for n, target in links(f):
        path = urllib.parse.unquote(target.split("#", 1)[0].split("?", 1)[0])
        dest = (f.parent / path).resolve()
        if not dest.exists():
            print(f"FAIL: {rel}:{n}: link to a missing file: {target}")
            problems += 1
        elif dest.suffix == ".md":
            graph[f].add(dest)

roots = [root / "README.md", root / "docs" / "index.md"]
if not roots[1].exists():
    print("FAIL: docs/index.md is missing")
    sys.exit(1)
seen, todo = set(roots), list(roots)
while todo:
    for dest in graph.get(todo.pop(), ()):
        if dest not in seen:
            seen.add(dest)
            todo.append(dest)
for p in pages:
    if p not in seen:
        print(f"FAIL: {p.relative_to(root)}: not linked from docs/index.md or README.md "
              "(directly or through a linked page)")
        problems += 1

if problems:
    sys.exit(1)
print(f"PASS: README.md and {len(pages)} pages under docs/: every page linked, "
      "every relative link and image found")
PY
if ((fail == 0)); then
  echo "PASS: README.md has $lines lines; no issue or work-step numbers in README.md or docs/"
fi
exit $fail
