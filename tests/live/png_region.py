#!/usr/bin/env python3
"""png_region.py WINDOW.png IMAGE.png X Y: exit 0 when IMAGE appears in WINDOW at (X, Y), pixel
for pixel (RGB, each channel within 2 of the other), else 1 with the first differing pixel.
The live lab's test uses it to see that the docked panel leaves the view uncovered. Only what
passlab writes is read: 8-bit RGB or RGBA PNGs, not interlaced (zlib + the five PNG filters)."""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, w, h, channels = 8, b"", 0, 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit(f"{path}: only 8-bit RGB/RGBA, non-interlaced PNGs are read")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
    raw, stride = zlib.decompress(idat), w * channels
    rows, prev = [], bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, channels, rows


def main():
    win, img, x0, y0 = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    ww, wh, wc, wrows = read_png(win)
    iw, ih, ic, irows = read_png(img)
    if x0 + iw > ww or y0 + ih > wh:
        print(f"{img} ({iw}x{ih}) does not fit in {win} ({ww}x{wh}) at ({x0}, {y0})")
        return 1
    for y in range(ih):
        for x in range(iw):
            a = wrows[y0 + y][(x0 + x) * wc:(x0 + x) * wc + 3]
            b = irows[y][x * ic:x * ic + 3]
            if any(abs(p - q) > 2 for p, q in zip(a, b)):
                print(f"pixel ({x}, {y}) of {img} is {tuple(b)}, the window has {tuple(a)} at ({x0 + x}, {y0 + y})")
                return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
