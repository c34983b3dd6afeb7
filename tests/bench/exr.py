"""Reads the EXR files `passlab render` writes, with the Python standard library only.

passlab writes EXR through OpenImageIO as a single-part scanline image, four channels (A, B, G,
R, stored in that alphabetical order), FLOAT (or HALF with exr_half), ZIP compression: blocks of
16 scanlines, each zlib-deflated after two reversible filters (OpenEXR's ImfZip.cpp): a byte
predictor (each byte stored as the difference to the previous one, + 128) and an interleave (the
even bytes first, then the odd ones). A block whose compressed form would be larger is stored
raw. NO_COMPRESSION files (one scanline per block) are read too; other compressions are refused.

    from exr import read_exr
    w, h, rgba = read_exr("out/preset.radiance.exr")   # rgba: list of (r, g, b, a) tuples, row-major

Usable as a script: `python3 tests/bench/exr.py FILE` prints the size and the mean of each channel.
"""
import struct
import sys
import zlib

_LINES = {0: 1, 2: 1, 3: 16}  # compression -> scanlines per block: NONE, ZIPS, ZIP


def _header(data):
    if data[:4] != b"\x76\x2f\x31\x01":
        raise ValueError("not an OpenEXR file")
    if data[5] & 0x1A:  # version flags: tiled (bit 9), deep (11), multi-part (12)
        raise ValueError("tiled, deep or multi-part EXR: not written by passlab")
    pos, attrs = 8, {}
    while data[pos] != 0:
        end = data.index(b"\0", pos)
        name = data[pos:end].decode()
        end2 = data.index(b"\0", end + 1)
        typ = data[end + 1:end2].decode()
        (size,) = struct.unpack_from("<i", data, end2 + 1)
        attrs[name] = (typ, data[end2 + 5:end2 + 5 + size])
        pos = end2 + 5 + size
    return attrs, pos + 1


def _channels(raw):
    out, pos = [], 0
    while raw[pos] != 0:
        end = raw.index(b"\0", pos)
        (ptype,) = struct.unpack_from("<i", raw, end + 1)
        out.append((raw[pos:end].decode(), ptype))  # 1 = HALF, 2 = FLOAT
        pos = end + 1 + 16
    return out


def _unzip(block, expected):
    if len(block) == expected:
        return block  # stored raw: compression did not pay
    t = bytearray(zlib.decompress(block))
    for i in range(1, len(t)):
        t[i] = (t[i - 1] + t[i] - 128) & 0xFF
    half = (len(t) + 1) // 2
    out = bytearray(len(t))
    out[0::2] = t[:half]
    out[1::2] = t[half:]
    return bytes(out)


def read_exr(path):
    with open(path, "rb") as f:
        data = f.read()
    attrs, pos = _header(data)
    chans = _channels(attrs["channels"][1])
    comp = attrs["compression"][1][0]
    if comp not in _LINES:
        raise ValueError(f"{path}: EXR compression {comp} is not read here (passlab writes ZIP)")
    xmin, ymin, xmax, ymax = struct.unpack("<4i", attrs["dataWindow"][1])
    w, h = xmax - xmin + 1, ymax - ymin + 1
    lines = _LINES[comp]
    nblocks = (h + lines - 1) // lines
    offsets = struct.unpack_from(f"<{nblocks}Q", data, pos)
    sizes = [2 if t == 1 else 4 for _, t in chans]
    planes = {name: [0.0] * (w * h) for name, _ in chans}
    for off in offsets:
        y0, n = struct.unpack_from("<ii", data, off)
        y0 -= ymin
        rows = min(lines, h - y0)
        raw = _unzip(data[off + 8:off + 8 + n], rows * w * sum(sizes)) if comp else data[off + 8:off + 8 + n]
        p = 0
        for r in range(rows):
            for (name, t), sz in zip(chans, sizes):
                vals = struct.unpack_from(f"<{w}{'e' if t == 1 else 'f'}", raw, p)
                planes[name][(y0 + r) * w:(y0 + r + 1) * w] = vals
                p += w * sz
    one = [1.0] * (w * h)
    r, g, b = (planes.get(c, one) for c in "RGB")
    a = planes.get("A", one)
    return w, h, list(zip(r, g, b, a))


if __name__ == "__main__":
    w, h, px = read_exr(sys.argv[1])
    n = len(px)
    print(f"{w}x{h}", " ".join(f"{sum(p[c] for p in px) / n:.6g}" for c in range(4)))
