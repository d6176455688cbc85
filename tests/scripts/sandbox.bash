# shellcheck shell=bash
# Sourced by the scripts' tests (not a test itself: only *.sh are). A sandbox: a copy of the
# repository's scripts/ under $box/root (the scripts find their files from where they lie, so
# nothing of the repository can be overwritten), a stub shadowlab-cli ($stub_cli) that records
# each call in $box/cli.calls and writes the files its --csv, --chart, --out and --metrics name
# (a CSV row for --csv; STUB_NO_CSV=1: none), a scene file $scene, and checks that print
# "ok ..." or "FAIL ...".
# usage: source sandbox.bash REPOSITORY OUTDIR
set -uo pipefail
repo=$1 box=$2
rm -rf "$box"
mkdir -p "$box/root" "$box/out"
cp -R "$repo/scripts" "$box/root/scripts"
stub_cli=$box/shadowlab-cli
cat >"$stub_cli" <<'EOF'
#!/usr/bin/env bash
echo "$*" >>"$(dirname "$0")/cli.calls"
while (($#)); do
  case $1 in
    --csv)
      if [[ ${STUB_NO_CSV:-0} != 1 ]]; then
        mkdir -p "$(dirname "$2")"
        printf 'technique,params,camera,error_pct\nrtw-backward,resolution=512,path,1.0\n' >"$2"
      fi
      shift ;;
    --chart | --out | --metrics) mkdir -p "$(dirname "$2")" && echo stub >"$2" && shift ;;
  esac
  shift
done
echo "stub bench output"
EOF
chmod +x "$stub_cli"
mkdir -p "$box/scenes"
scene=$box/scenes/room.gltf
echo '{"asset": {"version": "2.0"}}' >"$scene"
fail=0

ok() { echo "ok   $*"; }
failed() {
  echo "FAIL $*"
  fail=1
}

# expect_refused WHAT 'message part' COMMAND...: COMMAND exits 2 within 20 s with one line on
# stderr that holds the message part, and calls no shadowlab-cli.
expect_refused() {
  local what=$1 part=$2 err rc=0
  shift 2
  rm -f "$box/cli.calls"
  err=$(cd "$box" && timeout 20 "$@" 2>&1 >/dev/null </dev/null) || rc=$?
  if ((rc == 124)); then
    failed "$what: still running after 20 s (blocked on the output?)"
  elif ((rc != 2)); then
    failed "$what: exit $rc, expected 2 (refused); it said: ${err:0:400}"
  elif [[ $err == *$'\n'* || $err != *"$part"* ]]; then
    failed "$what: expected one line holding '$part', got: $err"
  elif [[ -e $box/cli.calls ]]; then
    failed "$what: refused only after running shadowlab-cli ($(head -n 1 "$box/cli.calls"))"
  else
    ok "$what: $err"
  fi
}

# expect_content WHAT FILE TEXT: FILE (followed if a link) still holds exactly TEXT.
expect_content() {
  if [[ $(cat "$2" 2>/dev/null) == "$3" ]]; then
    ok "$1: '$2' untouched"
  else
    failed "$1: '$2' was changed (it holds: $(head -c 200 "$2" 2>/dev/null))"
  fi
}

# expect_link_refused WHAT LINK INPUT 'message part' COMMAND...: with LINK a symbolic link to
# the file INPUT, COMMAND is refused (expect_refused) and INPUT keeps its content; LINK is
# removed after.
expect_link_refused() {
  local what=$1 link=$2 input=$3 part=$4 before
  shift 4
  before=$(cat "$input")
  ln -s "$input" "$link"
  expect_refused "$what" "$part" "$@"
  expect_content "$what" "$input" "$before"
  rm -f "$link"
}

# expect_no_temporary WHAT DIR: no temporary file (a hidden .NAME.XXXXXX) is left in DIR.
expect_no_temporary() {
  local left
  left=$(find "$2" -name '.*.*' 2>/dev/null | head -n 3)
  if [[ -z $left ]]; then ok "$1: no temporary file left"; else failed "$1: left $left"; fi
}

# expect_good_run WHAT FILE PATTERN COMMAND...: COMMAND succeeds within 20 s, FILE holds a line
# matching PATTERN (grep) and no temporary file is left in $box/out.
expect_good_run() {
  local what=$1 file=$2 pattern=$3
  shift 3
  if (cd "$box" && timeout 20 "$@") >/dev/null 2>&1 && grep -q -- "$pattern" "$file"; then
    ok "$what: '$file' written"
  else
    failed "$what: the run failed or '$file' does not hold '$pattern'"
  fi
  expect_no_temporary "$what" "$box/out"
}

finish() {
  if ((fail)); then echo FAIL; else echo PASS; fi
  exit "$fail"
}
