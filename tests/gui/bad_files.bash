# Sourced by open_bad_gltf.sh and open_bad_session.sh (not a test itself: only *.sh are).
# check_bad_files SELFTEST MENU OUT RC FILE...: shadowlab-gui-tests --test SELFTEST=FILE,... exited
# with RC and wrote OUT/gui-test.stdout and OUT/gui-test.stderr; it must have passed, opened
# every FILE through MENU and by dropping it, and named each FILE on stderr both times.
check_bad_files() {
  local test=$1 menu=$2 out=$3 rc=$4 f name how
  shift 4
  cat "$out/gui-test.stdout"
  echo "(stderr: $(wc -c <"$out/gui-test.stderr") bytes)"
  if [[ $rc -ne 0 ]] || ! grep -qx PASS "$out/gui-test.stdout"; then
    echo "FAIL: GUI test $test exited with $rc; stderr (first 4000 bytes):"
    head -c 4000 "$out/gui-test.stderr"
    exit 1
  fi
  for f in "$@"; do
    name=$(basename "$f")
    for how in "$menu" dropped; do
      grep -qxF -- "---- $name, $how" "$out/gui-test.stdout" ||
        { echo "FAIL: the GUI test did not open $name ($how)"; exit 1; }
    done
    [[ $(grep -cF "$name" "$out/gui-test.stderr") -ge 2 ]] ||
      { echo "FAIL: stderr does not name $name twice (menu and drop)"; exit 1; }
  done
}
