#!/usr/bin/env bash
# scripts/grab_lessons.sh copies its grabs under the output policy, with a stub shadowlab (it
# saves a small PNG as the window) and no X server: a grab that links to a lesson file and one
# that is a FIFO (in the second size's folder) are refused in one line (exit 2) before the
# first grab, the lesson untouched; a good run writes every grab and leaves no temporary file.
# usage: grab_lessons.sh <repository root> <output folder>
source "$(dirname "$0")/sandbox.bash" "$1" "$2/grab_lessons"
root=$box/root
mkdir -p "$root/scenes/lessons" "$root/tests/gui"
echo '{"title": "A"}' >"$root/scenes/lessons/01-a.json"
echo '{"title": "B", "cases": [{}, {}]}' >"$root/scenes/lessons/02-b.json"
printf 'start_xvfb() { :; }\nstop_xvfb() { :; }\n' >"$root/tests/gui/xvfb.bash"
png=$box/window.png  # 1x1, grey
python3 - "$png" <<'PY'
import struct, sys, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
header = struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                              chunk(b"IDAT", zlib.compress(b"\x00\x80")) + chunk(b"IEND", b""))
PY
app=$box/shadowlab
cat >"$app" <<STUB
#!/usr/bin/env bash
echo "\$*" >>"$box/cli.calls"
while ((\$#)); do
  [[ \$1 == --grab ]] && mkdir -p "\$2" && cp "$png" "\$2/window.png"
  shift
done
STUB
chmod +x "$app"
export SIZES="64x64 32x32"

expect_link_refused "a grab links to a lesson" "$box/out/01-a.png" "$root/scenes/lessons/01-a.json" \
  "the grab '$box/out/01-a.png' is the same file as the lesson '$root/scenes/lessons/01-a.json'" \
  root/scripts/grab_lessons.sh "$box/out" "$app" 1

mkdir -p "$box/out/32x32"
mkfifo "$box/out/32x32/02-b-case2.png"
expect_refused "a grab of the second size is a FIFO" \
  "the grab '$box/out/32x32/02-b-case2.png' is a FIFO, not a regular file" \
  root/scripts/grab_lessons.sh "$box/out" "$app" 1
rm "$box/out/32x32/02-b-case2.png"

echo old >"$box/out/02-b.png"
if timeout 20 "$root/scripts/grab_lessons.sh" "$box/out" "$app" 1 >/dev/null &&
  cmp -s "$box/out/02-b.png" "$png" &&
  [[ -f $box/out/32x32/02-b-case2.png && -f $box/out/01-a.png ]]; then
  ok "a good run wrote every grab"
else
  failed "a good run: a grab is missing or was not replaced"
fi
expect_no_temporary "a good run" "$box/out"
finish
