#!/usr/bin/env bash
# shadowlab-cli on bad input: non-zero exit and one stderr line naming the problem.
set -uo pipefail
cli=$1 data=$2 out=$3
mkdir -p "$out"
fail=0
expect() {  # expect "substring" args...
  local want=$1; shift
  local err rc
  err=$("$cli" "$@" 2>&1 >/dev/null); rc=$?
  if [ $rc -eq 0 ]; then echo "FAIL (exit 0): $*"; fail=1; return; fi
  if [[ "$err" != *"$want"* ]]; then echo "FAIL: '$*' said '$err', expected '$want'"; fail=1; return; fi
  if [ "$(printf '%s\n' "$err" | wc -l)" -ne 1 ]; then echo "FAIL (not one line): $err"; fail=1; return; fi
  echo "ok: $err"
}
# expect_exactly RC "exact stderr line" args...: the exit status and the whole message.
expect_exactly() {
  local want_rc=$1 want=$2; shift 2
  local err rc=0
  err=$("$cli" "$@" 2>&1 >/dev/null) || rc=$?
  if [ $rc -ne "$want_rc" ]; then echo "FAIL (exit $rc, expected $want_rc): $*: $err"; fail=1; return; fi
  if [ "$err" != "$want" ]; then echo "FAIL: '$*' said '$err', expected '$want'"; fail=1; return; fi
  echo "ok: $err"
}
o="--out $out/x.png"
expect "nonexistent.gltf" render --scene /nonexistent.gltf --technique uniform $o
expect "malformed.gltf" render --scene "$data/malformed.gltf" --technique uniform $o
expect "truncated.glb" render --scene "$data/truncated.glb" --technique uniform $o
expect "no-triangles.gltf" render --scene "$data/no-triangles.gltf" --technique uniform $o
expect "nan-position.gltf" render --scene "$data/nan-position.gltf" --technique uniform $o
expect "KHR_draco_mesh_compression" render --scene "$data/draco-required.gltf" --technique uniform $o
expect "unknown technique 'nope'" render --scene plane-box --technique nope $o
expect "unknown parameter 'bogus'" render --scene plane-box --technique uniform --set bogus=1 $o
expect "64..16384" render --scene plane-box --technique uniform --set resolution=99999 $o
expect "--size" render --scene plane-box --technique uniform --size 0x10 $o
expect "--out" render --scene plane-box --technique uniform
expect "unknown command" frobnicate
expect "no camera" render --scene plane-box --technique uniform --camera nope $o
# An option's value that is the next option is no value (issue 14).
expect_exactly 2 "shadowlab-cli: --scene: missing value (got the option '--size')" \
  render --scene --size 64x36 $o
expect_exactly 2 "shadowlab-cli: --csv: missing value (got the option '--chart')" \
  bench --scene plane-box --technique uniform --csv --chart "$out/x.png"
# A frame larger than the GL implementation renders: refused naming the limit, before
# anything is allocated (llvmpipe: 16384 per side, and no single texture over 1 GiB).
too_wide="20000x100 is wider than this OpenGL implementation renders (GL_MAX_TEXTURE_SIZE 16384)"
expect_exactly 2 "shadowlab-cli: --size: $too_wide" \
  render --scene plane-box --technique uniform --size 20000x100 $o
expect_exactly 2 "shadowlab-cli: --size: 100x20000 is taller than this OpenGL implementation renders (GL_MAX_TEXTURE_SIZE 16384)" \
  render --scene plane-box --technique uniform --size 100x20000 $o
expect_exactly 2 "shadowlab-cli: --size: 16384x16384 is larger than this OpenGL implementation allocates (a 16384x16384 RGBA32F G-buffer target is refused by GL_PROXY_TEXTURE_2D)" \
  render --scene plane-box --technique uniform --size 16384x16384 $o
expect_exactly 2 "shadowlab-cli: --size: $too_wide" \
  bench --scene plane-box --technique uniform --size 20000x100 --csv "$out/x.csv"
expect_exactly 2 "shadowlab-cli: --size: $too_wide" \
  stability --scene plane-box --technique uniform --size 20000x100 --json "$out/x.json"
expect_exactly 2 "shadowlab-cli: --size: $too_wide" \
  stability --suite "$(dirname "$0")/../../scenes/suites/failure-cases.json" --size 20000x100
expect_exactly 2 "shadowlab-cli: --size: $too_wide" \
  compare --scene plane-box --size 20000x100 --out-dir "$out/cmp-too-wide"
# A driver without OpenGL 4.5 (Mesa can pretend): the message names the missing version.
export MESA_GL_VERSION_OVERRIDE=3.3
expect "OpenGL 4.5" render --scene plane-box --technique uniform $o
unset MESA_GL_VERSION_OVERRIDE
exit $fail
