# Sourced by the GUI tests (not a test itself: only *.sh are): starts a private Xvfb on a
# display the server picks itself (-displayfd, no race with other runs), waits until it
# answers, exports DISPLAY and kills it on exit. XVFB_SCREEN (default 1600x1000x24) sets the
# screen's size.
XVFB_PID=""
XVFB_TMP=""

stop_xvfb() {
  if [[ -n "$XVFB_PID" ]]; then
    kill "$XVFB_PID" 2>/dev/null || true
    wait "$XVFB_PID" 2>/dev/null || true
    XVFB_PID=""
  fi
  [[ -n "$XVFB_TMP" ]] && rm -rf "$XVFB_TMP"
  XVFB_TMP=""
}

start_xvfb() {
  XVFB_TMP=$(mktemp -d "${TMPDIR:-/tmp}/shadowlab-xvfb.XXXXXX")
  trap stop_xvfb EXIT
  Xvfb -displayfd 3 -screen 0 "${XVFB_SCREEN:-1600x1000x24}" -nolisten tcp -nolisten unix-abstract \
    3>"$XVFB_TMP/display" 2>"$XVFB_TMP/xvfb.log" &
  XVFB_PID=$!
  local display=""
  for _ in $(seq 200); do  # up to 20 s
    if ! kill -0 "$XVFB_PID" 2>/dev/null; then
      echo "FAIL: Xvfb exited early:" >&2
      cat "$XVFB_TMP/xvfb.log" >&2
      return 1
    fi
    display=$(head -n1 "$XVFB_TMP/display" 2>/dev/null || true)
    [[ -n "$display" ]] && break
    sleep 0.1
  done
  if [[ -z "$display" ]]; then
    echo "FAIL: Xvfb did not report a display within 20 s" >&2
    return 1
  fi
  export DISPLAY=":$display"
  # Qt: the default xcb platform (offscreen has no usable GL), quiet runtime dir.
  unset QT_QPA_PLATFORM
  export XDG_RUNTIME_DIR="$XVFB_TMP/runtime"
  mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
  if command -v xdpyinfo >/dev/null; then
    xdpyinfo >/dev/null 2>&1 || { echo "FAIL: Xvfb on $DISPLAY does not answer" >&2; return 1; }
  fi
  echo "Xvfb on $DISPLAY (pid $XVFB_PID)"
}

# Runs a shadowlab GUI test: run_gui_test <what> <timeout s> <log prefix> <command...>.
# Its stdout is printed and kept in <log prefix>.stdout, its stderr in <log prefix>.stderr;
# the calling test fails (exit 1, the stderr shown) unless it exited 0 and printed a line PASS.
run_gui_test() {
  local what=$1 limit=$2 log=$3
  shift 3
  local rc=0
  timeout "$limit" "$@" >"$log.stdout" 2>"$log.stderr" || rc=$?
  cat "$log.stdout"
  if [[ $rc -ne 0 ]] || ! grep -qx PASS "$log.stdout"; then
    echo "FAIL: $what exited with $rc; stderr:"
    cat "$log.stderr"
    exit 1
  fi
}
