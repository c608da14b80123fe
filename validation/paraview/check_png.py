#!/usr/bin/env python3
"""Check that rendered PNGs show something: python3 check_png.py IMAGE.png [IMAGE.png ...]

A render that failed silently gives an empty file, or an image of one flat colour (the background),
or almost only background. Each image must decode, and must have at least MIN_COLOURS distinct
colours with no single colour covering more than MAX_SHARE of the pixels.
Standard library only: the PNG is decoded here (8-bit greyscale/RGB/RGBA, non-interlaced, which is
what VTK writes).
"""
import struct
import sys
import zlib
from collections import Counter

MIN_COLOURS = 16
MAX_SHARE = 0.98
CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type → samples per pixel


class PngError(Exception):
    pass


def read_chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise PngError("not a PNG file")
    pos = 8
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        yield kind, data[pos + 8:pos + 8 + length]
        pos += 12 + length


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def decode(path):
    """Return (width, height, rows) with rows as lists of pixel tuples."""
    with open(path, "rb") as f:
        data = f.read()
    header, compressed = None, b""
    for kind, body in read_chunks(data):
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            compressed += body
    if header is None:
        raise PngError("no IHDR chunk")
    width, height, depth, colour_type, _, _, interlace = header
    if depth != 8 or colour_type not in CHANNELS or interlace != 0:
        raise PngError("unsupported PNG (depth %d, colour type %d, interlace %d)" % (depth, colour_type, interlace))
    bpp = CHANNELS[colour_type]
    raw = zlib.decompress(compressed)
    stride = width * bpp
    if len(raw) != height * (stride + 1):
        raise PngError("image data has %d bytes, expected %d" % (len(raw), height * (stride + 1)))
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        filter_type, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            left = line[i - bpp] if i >= bpp else 0
            up = previous[i]
            up_left = previous[i - bpp] if i >= bpp else 0
            if filter_type == 1:
                line[i] = (line[i] + left) & 0xFF
            elif filter_type == 2:
                line[i] = (line[i] + up) & 0xFF
            elif filter_type == 3:
                line[i] = (line[i] + ((left + up) >> 1)) & 0xFF
            elif filter_type == 4:
                line[i] = (line[i] + paeth(left, up, up_left)) & 0xFF
            elif filter_type != 0:
                raise PngError("unknown filter type %d in row %d" % (filter_type, y))
        rows.append([tuple(line[x * bpp:(x + 1) * bpp]) for x in range(width)])
        previous = line
    return width, height, rows


def check(path):
    """Return a list of problems (empty when the image is fine)."""
    try:
        width, height, rows = decode(path)
    except (OSError, PngError, zlib.error, struct.error) as e:
        return ["%s: %s" % (path, e)]
    if width == 0 or height == 0:
        return ["%s: empty image" % path]
    counts = Counter(pixel for row in rows for pixel in row)
    colour, most = counts.most_common(1)[0]
    share = most / float(width * height)
    problems = []
    if len(counts) < MIN_COLOURS:
        problems.append("%s: only %d distinct colours (need %d)" % (path, len(counts), MIN_COLOURS))
    if share > MAX_SHARE:
        problems.append("%s: colour %s covers %.1f%% of the image" % (path, colour, 100 * share))
    if not problems:
        print("%s: %dx%d, %d colours, background %.1f%%" % (path, width, height, len(counts), 100 * share))
    return problems


def main(paths):
    if not paths:
        sys.stderr.write("usage: check_png.py IMAGE.png [IMAGE.png ...]\n")
        return 2
    problems = [p for path in paths for p in check(path)]
    for problem in problems:
        sys.stderr.write("error: %s\n" % problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
