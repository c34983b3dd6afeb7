#!/usr/bin/env python3
"""The expected values of the closed-form probes added to presets/texturing
(multitexture-gloss-map, mipmapping, light-mapping, projective-texture, anisotropic-filtering),
evaluated in float64 from the formulas the shaders and the host use (the PCG3D hash of
passes/common/hash.glsl, host/image/procedural.cpp's checker, host/scene/camera.cpp's orbit
camera and glm::lookAt, passes/common/camera.glsl). Run: python3 closed_forms.py
"""
import math
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'passes', 'common'))
from hash import M, pcg3d, hash_pcg, hash_pcg3  # passes/common/hash.glsl's twin
def srgb(v): return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055

def multitexture():
    # third thumbnail of 256x144: side 0.22 x 144, t = (fract(x / side), 1 - y_from_bottom / side), id_map 1:1
    W, H = 256, 144; side = 0.22 * H
    for x, y in [(88, 138), (92, 121), (65, 133), (77, 115), (70, 134)]:
        px, py = x + 0.5, H - y - 0.5
        t = ((px / side) % 1.0, 1 - py / side)
        tex = (math.floor(t[0] * 256), math.floor(t[1] * 256))
        cell = (math.floor((tex[0] + 0.5) / 256 * 8), math.floor((tex[1] + 0.5) / 256 * 8))
        m = math.floor(hash_pcg((cell[0], cell[1], 2.0)) * 4)
        print('multitexture thumbnail', (x, y), 'material', m, 'stored', round(srgb((m + 0.5) / 4), 6))
    print('multitexture background stored', [round(srgb(c), 6) for c in (0.03, 0.035, 0.045)])

def mipmapping():
    # 330x64 from straight above: lookAt at pitch 90 puts screen right along -x, screen up along +z
    W, H, d = 330, 64, 1.5028; th = math.tan(math.radians(25))
    for px in [3, 50, 101, 103, 105, 107]:
        for py in [5, 20]:
            nx, ny = (px + 0.5) / W * 2 - 1, 1 - (py + 0.5) / H * 2
            x, z = -nx * th * W / H * d, ny * th * d
            S, T = (x / 20 + 0.5) * 48 * 64, (z / 20 + 0.5) * 48 * 64
            X, Y = int(math.floor(S)) % 64, int(math.floor(T)) % 64
            margin = min(S % 1, 1 - S % 1, T % 1, 1 - T % 1)
            print('mipmapping nearest', (px, py), 1.0 if (X // 2 + Y // 2) % 2 == 0 else 0.0, 'texel margin', round(margin, 3))

def light_mapping():
    ball = (0.1, 0.45, 0.0, 0.3)
    L = [((-0.9, 1.1, 0.5), (1.3, 1.05, 0.8)), ((1.2, 0.8, -0.8), (0.35, 0.5, 0.8))]
    for i, j in [(20, 15), (12, 20), (0, 0), (27, 5)]:
        p = (((i + 0.5) / 32 - 0.5) * 4, 0.0, ((j + 0.5) / 32 - 0.5) * 4)
        e = [0.03, 0.03, 0.035]
        for pos, col in L:
            dd = [pos[k] - p[k] for k in range(3)]; m = [p[k] - ball[k] for k in range(3)]
            a = sum(x * x for x in dd); b = sum(m[k] * dd[k] for k in range(3)); c = sum(x * x for x in m) - ball[3] ** 2
            disc = b * b - a * c
            if disc >= 0 and 1e-4 < (-b - math.sqrt(disc)) / a < 1: continue
            for k in range(3): e[k] += col[k] * max(dd[1] / math.sqrt(a), 0) / a
        print('light-mapping texel', (i, j), [round(x, 6) for x in e])

def projective():
    W, H = 320, 180; th = math.tan(math.radians(27.5))
    eye, tgt = (0, 0.6, 0.5), (0, 0.9, -3.0)
    f = [tgt[k] - eye[k] for k in range(3)]; n = math.sqrt(sum(x * x for x in f)); f = [x / n for x in f]
    r = (1.0, 0.0, 0.0); u = (r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0])
    t0 = 1 / math.tan(math.radians(20))
    for px, py in [(228, 40), (230, 60), (230, 80)]:
        X = ((px + 0.5) / W * 2 - 1) * th * W / H * 3.5; Y = 0.9 + (1 - (py + 0.5) / H * 2) * th * 3.5
        dd = [X - eye[0], Y - eye[1], -3.0 - eye[2]]; zf = sum(f[k] * dd[k] for k in range(3))
        s = 0.5 + 0.5 * t0 * dd[0] / zf; t = 0.5 - 0.5 * t0 * sum(u[k] * dd[k] for k in range(3)) / zf
        print('projective wall', (px, py), 'world', (round(X, 3), round(Y, 3)), 'st', (round(s, 4), round(t, 4)))

def aniso_count(n=2):
    W = H = 128
    eye = (0.0, 3 * math.sin(math.radians(5)), -1 + 3 * math.cos(math.radians(5)))
    f = [0 - eye[0], 0 - eye[1], -1 - eye[2]]; l = math.sqrt(sum(x * x for x in f)); f = [x / l for x in f]
    r = (-f[2], 0.0, f[0]); l = math.sqrt(r[0] ** 2 + r[2] ** 2); r = (r[0] / l, 0.0, r[2] / l)
    u = (r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0])
    th = math.tan(math.radians(25))
    def hit(x, y):
        nx, ny = x / W * 2 - 1, y / H * 2 - 1
        d = [f[k] + r[k] * nx * th + u[k] * (-ny) * th for k in range(3)]
        if d[1] >= 0: return False
        s = -eye[1] / d[1]; p = [eye[k] + s * d[k] for k in range(3)]
        return abs(p[0]) <= 10 and -30 <= p[2] <= 2
    offs = [(k + 0.5) / n for k in (0, n - 1)]   # the plane's image is convex: the extreme samples decide
    cnt = sum(all(hit(px + ox, py + oy) for ox in offs for oy in offs) for py in range(H) for px in range(W))
    print('anisotropic-filtering pixels fully on the plane, ref_grid', n, cnt)

if __name__ == '__main__':
    multitexture(); mipmapping(); light_mapping(); projective(); aniso_count()
