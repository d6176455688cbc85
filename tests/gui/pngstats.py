#!/usr/bin/env python3
"""Checks that PNG files are real pictures, not blank: reads them with the standard
library only (zlib; 8-bit greyscale/RGB/RGBA/palette, non-interlaced, all PNG filters) and
prints size, distinct colours and the luminance standard deviation.

usage: pngstats.py [--min-colors N] [--min-stddev S] [--min-size WxH] FILE...
Exit 0 when every file passes, 1 otherwise (with a line naming the file and the reason).
"""
import argparse
import struct
import sys
import zlib


def unfilter(ftype, line, prev, bpp):
    """Undoes one PNG row filter in place (one loop per filter type: this is the hot part)."""
    n = len(line)
    if ftype == 0:
        return
    if ftype == 1:
        for i in range(bpp, n):
            line[i] = (line[i] + line[i - bpp]) & 255
    elif ftype == 2:
        for i in range(n):
            line[i] = (line[i] + prev[i]) & 255
    elif ftype == 3:
        for i in range(bpp):
            line[i] = (line[i] + (prev[i] >> 1)) & 255
        for i in range(bpp, n):
            line[i] = (line[i] + ((line[i - bpp] + prev[i]) >> 1)) & 255
    elif ftype == 4:
        for i in range(bpp):
            line[i] = (line[i] + prev[i]) & 255
        for i in range(bpp, n):
            a, b, c = line[i - bpp], prev[i], prev[i - bpp]
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else (b if pb <= pc else c))) & 255
    else:
        raise ValueError(f"bad PNG filter type {ftype}")


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, palette = 8, [], None
    width = height = depth = ctype = interlace = None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"PLTE":
            palette = [tuple(body[i:i + 3]) for i in range(0, len(body), 3)]
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if width is None:
        raise ValueError("no IHDR chunk")
    if depth != 8 or interlace != 0:
        raise ValueError(f"unsupported PNG (bit depth {depth}, interlace {interlace})")
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        ftype, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        unfilter(ftype, line, prev, channels)
        rows.append(bytes(line))
        prev = line
    return width, height, ctype, channels, palette, rows


def stats(path):
    width, height, ctype, channels, palette, rows = read_png(path)
    colours, n, total, total2 = set(), 0, 0.0, 0.0
    step = max(1, (width * height) // 250000)  # sample big images
    for row in rows[::step]:
        for x in range(0, width, step):
            px = row[x * channels:(x + 1) * channels]
            if ctype == 3:
                rgb = palette[px[0]]
            elif channels <= 2:
                rgb = (px[0],) * 3
            else:
                rgb = tuple(px[:3])
            colours.add(rgb)
            lum = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
            n += 1
            total += lum
            total2 += lum * lum
    mean = total / n
    stddev = max(0.0, total2 / n - mean * mean) ** 0.5
    return width, height, len(colours), mean, stddev


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--min-colors", type=int, default=2)
    ap.add_argument("--min-stddev", type=float, default=0.0)
    ap.add_argument("--min-size", default="1x1")
    ap.add_argument("files", nargs="+")
    args = ap.parse_args()
    min_w, min_h = (int(v) for v in args.min_size.lower().split("x"))
    ok = True
    for path in args.files:
        try:
            w, h, colours, mean, sd = stats(path)
        except (OSError, ValueError, zlib.error) as e:
            print(f"FAIL {path}: {e}")
            ok = False
            continue
        line = f"{path}: {w}x{h}, {colours} colours, mean {mean:.1f}, stddev {sd:.1f}"
        reasons = []
        if w < min_w or h < min_h:
            reasons.append(f"smaller than {min_w}x{min_h}")
        if colours < args.min_colors:
            reasons.append(f"fewer than {args.min_colors} colours")
        if sd < args.min_stddev:
            reasons.append(f"luminance stddev below {args.min_stddev}")
        print(("FAIL " if reasons else "ok   ") + line + ("" if not reasons else " (" + "; ".join(reasons) + ")"))
        ok = ok and not reasons
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
