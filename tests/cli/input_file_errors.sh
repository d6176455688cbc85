#!/usr/bin/env bash
# Filesystem errors on the files the CLI reads itself (--preset, --suite, chart --csv) exit 2
# with one line naming the file and what is wrong (issue 14): missing, a folder, a folder
# that is a file, and a file that cannot be opened (unreadable: run as another user when
# root, since root reads anything).
set -uo pipefail
cli=$1 out=$3/input-file-errors
rm -rf "$out" && mkdir -p "$out/w" && chmod 777 "$out" "$out/w"
cd "$out" || exit 1
fail=0
p="shadowlab-cli"

expect() {  # expect EXPECTED_LINE ARGS...: exit 2, stderr exactly one line
  local want=$1 err rc
  shift
  err=$(timeout 60 "${as[@]}" "$cli" "$@" 2>&1 >/dev/null)
  rc=$?
  if [ $rc -ne 2 ] || [ "$err" != "$want" ]; then
    printf 'FAIL: %s exited %s saying:\n  %s\nexpected (exit 2):\n  %s\n' "$*" "$rc" "$err" "$want"
    fail=1
  fi
}
# each CASE FILE: the three readers given FILE; CASE is the text after "FILE: ".
each() {
  expect "$p: --preset: $2: $1" render --preset "$2" --size 16x16 --out "$out/w/p.png"
  expect "$p: $2: $1" stability --suite "$2" --json "$out/w/s.json"
  expect "$p: $2: $1" chart --csv "$2" --chart "$out/w/c.png"
}

as=()
each "file not found" missing.json
each "file not found" missing-dir/x.json
echo x >plain
each "file not found" plain/x.json
mkdir folder
each "is a directory, not a regular file: refused (only regular files are read)" folder

echo '{}' >unreadable.json && chmod 000 unreadable.json
if [ "$(id -u)" -ne 0 ]; then
  each "cannot be opened for reading: Permission denied" unreadable.json
elif command -v setpriv >/dev/null && setpriv --reuid=65534 --regid=65534 --clear-groups \
    test -x "$cli" 2>/dev/null; then
  as=(setpriv --reuid=65534 --regid=65534 --clear-groups)
  each "cannot be opened for reading: Permission denied" unreadable.json
else
  echo "skipped: unreadable file (root, and no other user can run $cli)"
fi

[ $fail -eq 0 ] && echo "input file errors: ok"
exit $fail
