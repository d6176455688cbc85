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
# A driver without OpenGL 4.5 (Mesa can pretend): the message names the missing version.
export MESA_GL_VERSION_OVERRIDE=3.3
expect "OpenGL 4.5" render --scene plane-box --technique uniform $o
unset MESA_GL_VERSION_OVERRIDE
exit $fail
