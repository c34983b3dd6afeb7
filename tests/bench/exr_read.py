"""Reads the scanline OpenEXR files `passlab render --format exr` writes (NONE, ZIPS or ZIP
compression; HALF or FLOAT channels), python3 stdlib only: read(path) -> (width, height,
{channel: [values, row-major]})."""
import struct
import zlib


def _attributes(d):
    i, attrs = 8, {}
    while d[i] != 0:
        j = d.index(b"\0", i)
        k = d.index(b"\0", j + 1)
        size = int.from_bytes(d[k + 1:k + 5], "little")
        attrs[d[i:j].decode()] = d[k + 5:k + 5 + size]
        i = k + 5 + size
    return attrs, i + 1


def _channels(blob):
    out, i = [], 0
    while blob[i] != 0:
        j = blob.index(b"\0", i)
        pixel_type = int.from_bytes(blob[j + 1:j + 5], "little")
        out.append((blob[i:j].decode(), pixel_type))
        i = j + 17
    return out


def _unzip(data, expected):
    raw = bytearray(zlib.decompress(data))
    if len(raw) != expected:
        raise ValueError("bad ZIP block")
    for n in range(1, len(raw)):  # undo the predictor
        raw[n] = (raw[n - 1] + raw[n] - 128) & 0xFF
    half = (len(raw) + 1) // 2  # undo the byte interleave
    out = bytearray(len(raw))
    out[0::2] = raw[:half]
    out[1::2] = raw[half:]
    return bytes(out)


def read(path):
    d = open(path, "rb").read()
    if d[:4] != b"v/1\x01":
        raise ValueError(path + ": not an OpenEXR file")
    attrs, at = _attributes(d)
    channels = _channels(attrs["channels"])
    compression = attrs["compression"][0]
    x0, y0, x1, y1 = struct.unpack("<4i", attrs["dataWindow"])
    w, h = x1 - x0 + 1, y1 - y0 + 1
    lines = {0: 1, 2: 1, 3: 16}[compression]
    blocks = (h + lines - 1) // lines
    offsets = struct.unpack("<%dQ" % blocks, d[at:at + 8 * blocks])
    sizes = [2 if t == 1 else 4 for _, t in channels]
    values = {name: [0.0] * (w * h) for name, _ in channels}
    for off in offsets:
        y, size = struct.unpack("<ii", d[off:off + 8])
        data = d[off + 8:off + 8 + size]
        n = min(lines, y1 + 1 - y)
        expected = n * w * sum(sizes)
        if compression != 0 and size < expected:
            data = _unzip(data, expected)
        p = 0
        for row in range(n):
            for (name, t), s in zip(channels, sizes):
                fmt = "<%d%s" % (w, "e" if t == 1 else ("f" if t == 2 else "I"))
                vals = struct.unpack(fmt, data[p:p + w * s])
                base = (y - y0 + row) * w
                values[name][base:base + w] = vals
                p += w * s
    return w, h, values
