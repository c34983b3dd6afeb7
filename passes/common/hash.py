"""The Python twin of passes/common/hash.glsl, for scripts that compute a preset's expected
probe values on the host (presets/*/closed_forms.py). PCG3D (Jarzynski and Olano 2020) is integer
arithmetic on 32-bit words, so these values equal the shader's exactly; hash_pcg and hash_pcg3
map a cell to [0, 1) as hash.glsl's do (the float cast of ivec3(cell), then uvec3)."""
M = 0xffffffff


def pcg3d(x, y, z):
    x = (x * 1664525 + 1013904223) & M; y = (y * 1664525 + 1013904223) & M; z = (z * 1664525 + 1013904223) & M
    x = (x + y * z) & M; y = (y + z * x) & M; z = (z + x * y) & M
    x ^= x >> 16; y ^= y >> 16; z ^= z >> 16
    x = (x + y * z) & M; y = (y + z * x) & M; z = (z + x * y) & M
    return x, y, z


def _word(v):
    return int(v) & M  # ivec3(cell) then uvec3: truncation towards zero, two's complement


def hash_pcg(c):
    return pcg3d(_word(c[0]), _word(c[1]), _word(c[2]))[0] / 4294967296.0


def hash_pcg3(c):
    return tuple(v / 4294967296.0 for v in pcg3d(_word(c[0]), _word(c[1]), _word(c[2])))
