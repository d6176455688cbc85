#!/usr/bin/env bash
# docs/user-guide/parameters.md is `shadowlab-cli list --format markdown`, generated from the
# parameter declarations: this fails when a declaration changed and the page was not
# regenerated (the diff says what changed). Regenerate with
#   build/app/shadowlab-cli list --format markdown > docs/user-guide/parameters.md
set -euo pipefail
cli=$1 root=$(cd "$2/../.." && pwd) out=$3/parameter_reference
mkdir -p "$out"
page="$root/docs/user-guide/parameters.md"
"$cli" list --format markdown >"$out/parameters.md"
grep -q '^## uniform$' "$out/parameters.md" || { echo "FAIL: no technique sections"; exit 1; }
grep -q '^| `resolution` |' "$out/parameters.md" || { echo "FAIL: no parameter rows"; exit 1; }
if ! diff -u "$page" "$out/parameters.md" >"$out/diff.txt"; then
  echo "FAIL: $page is stale; regenerate it with:"
  echo "  shadowlab-cli list --format markdown > docs/user-guide/parameters.md"
  head -40 "$out/diff.txt"
  exit 1
fi
# Bad options: one line, exit 2.
set +e
msg=$("$cli" list --format html 2>&1); rc=$?
set -e
[ $rc -eq 2 ] && grep -q -- "--format: expected text or markdown" <<<"$msg" ||
  { echo "FAIL: list --format html: rc $rc, '$msg'"; exit 1; }
echo "PASS: docs/user-guide/parameters.md matches the declarations"
