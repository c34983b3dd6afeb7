#!/usr/bin/env python3
"""The expected values of the closed-form probes added to presets/procedural (brick,
fbm, hash-spectral-test, simplex-noise, value-noise, warped-noise), evaluated in float64 from
the same formulas the shaders use: the PCG3D hash of passes/common/hash.glsl is integer
arithmetic, so the lattice values and gradients are exact. Run: python3 closed_forms.py
"""
import math
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'passes', 'common'))
from hash import M, pcg3d, hash_pcg, hash_pcg3  # passes/common/hash.glsl's twin
def fade3(t): return t*t*(3-2*t)
def fade5(t): return t*t*t*(t*(t*6-15)+10)
def mix(a,b,t): return a+(b-a)*t
def value_noise(p, margin):
    i=[math.floor(c) for c in p]; fr=[c-math.floor(c) for c in p]
    margin[0]=min(margin[0], *[min(f,1-f) for f in fr])
    f=[fade3(t) for t in fr]
    n=lambda a,b,c: hash_pcg((i[0]+a,i[1]+b,i[2]+c))
    return mix(mix(mix(n(0,0,0),n(1,0,0),f[0]),mix(n(0,1,0),n(1,1,0),f[0]),f[1]),
               mix(mix(n(0,0,1),n(1,0,1),f[0]),mix(n(0,1,1),n(1,1,1),f[0]),f[1]),f[2])
def gradient_noise(p, margin):
    i=[math.floor(c) for c in p]; fr=[c-math.floor(c) for c in p]
    margin[0]=min(margin[0], *[min(f,1-f) for f in fr])
    uu=[fade5(t) for t in fr]
    def g(o):
        h=hash_pcg3((i[0]+o[0],i[1]+o[1],i[2]+o[2]))
        v=[2*hh-1+1e-6 for hh in h]; l=math.sqrt(sum(a*a for a in v)); v=[a/l for a in v]
        return sum(v[k]*(fr[k]-o[k]) for k in range(3))
    n=lambda a,b,c: g((a,b,c))
    return mix(mix(mix(n(0,0,0),n(1,0,0),uu[0]),mix(n(0,1,0),n(1,1,0),uu[0]),uu[1]),
               mix(mix(n(0,0,1),n(1,0,1),uu[0]),mix(n(0,1,1),n(1,1,1),uu[0]),uu[1]),uu[2])


# ---- the cases (each prints what its probes expect) ----
def srgb(v): return 12.92 * v if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055

def brick():
    L = (1.0, 1.5, 3.0)
    for px, py in [(395, 260), (395, 300), (100, 500)]:
        x, y = (px + 0.5) / 320 - 1, 1 - (py + 0.5) / 320
        b = 3 / math.sqrt((L[0] - x) ** 2 + (L[1] - y) ** 2 + 9)
        rx, ry = x / 0.25, y / 0.125
        if abs(ry) % 2 > 1: rx += 0.5
        rx -= math.floor(rx); ry -= math.floor(ry)
        c = (0.82, 0.8, 0.75) if (rx > 0.9 or ry > 0.85) else (0.62, 0.22, 0.12)
        print('brick', (px, py), 'hdr', [round(k * b, 6) for k in c], 'rel_pos', (round(rx, 6), round(ry, 6)))

def fbm():
    R = [[0.00, 0.80, 0.60], [-0.80, 0.36, -0.48], [-0.60, -0.48, 0.64]]  # GLSL columns
    W, H, t = 160, 96, 0.5
    for px, py in [(10, 10), (150, 12), (20, 85), (140, 80), (80, 48), (47, 61)]:
        p = [((px + 0.5) / W - 0.5) * W / H * 4.0, ((py + 0.5) / H - 0.5) * 4.0, t * 0.1]
        f = s = 0; amp = 1; mm = 0; mg = [1]
        for i in range(6):
            f += amp * value_noise(p, mg); s += amp
            p = [sum(R[j][k] * p[j] for j in range(3)) * (2 + mm) for k in range(3)]
            p = [p[0] + 17.13, p[1] + 31.71, p[2] + 5.37]; amp *= 0.5; mm += 0.0059
        print('fbm', (px, py), [round(f / s, 6), round(f, 6), s], 'lattice margin', round(mg[0], 4))

def randu_scatter(seed=3, n=30000, H=256):
    import collections
    cnt = collections.Counter()
    for i in range(n):
        st = (pow(65539, i, 2 ** 32) * (seed | 1)) & 0x7fffffff
        u0 = (st << 1) & 0xffffffff; st = (st * 65539) & 0x7fffffff; u1 = (st << 1) & 0xffffffff
        cnt[(math.floor(u0 / 2 ** 32 * H), math.floor((1 - u1 / 2 ** 32) * H))] += 1
    for k in [(9, 90), (48, 244), (111, 147), (138, 153), (190, 18), (208, 198), (209, 24), (242, 22), (22, 219), (172, 87), (220, 173)]:
        print('hash-spectral-test scatter', k, cnt[k])
    print('points counted (point 0 lands on pixel 0 centre\'s edge: 29999 drawn)', sum(cnt.values()))

def simplex_noise(p, mg):
    F2, G2 = 0.36602540378, 0.21132486540
    s = (p[0] + p[1]) * F2; i = (math.floor(p[0] + s), math.floor(p[1] + s))
    mg[0] = min(mg[0], abs(p[0] + s - round(p[0] + s)), abs(p[1] + s - round(p[1] + s)))
    c = (i[0] - (i[0] + i[1]) * G2, i[1] - (i[0] + i[1]) * G2); x0 = (p[0] - c[0], p[1] - c[1])
    mg[0] = min(mg[0], abs(x0[0] - x0[1]))
    o = (1.0, 0.0) if x0[0] > x0[1] else (0.0, 1.0)
    x1 = (x0[0] - o[0] + G2, x0[1] - o[1] + G2); x2 = (x0[0] - 1 + 2 * G2, x0[1] - 1 + 2 * G2)
    n = 0
    for cc, off in [(i, x0), ((i[0] + o[0], i[1] + o[1]), x1), ((i[0] + 1, i[1] + 1), x2)]:
        t = 0.5 - (off[0] ** 2 + off[1] ** 2)
        if t > 0:
            a = 6.2831853 * hash_pcg((cc[0], cc[1], 7))
            n += t ** 4 * (math.cos(a) * off[0] + math.sin(a) * off[1])
    return 70 * n

def simplex():
    W, H = 160, 96
    def field(px, py, octaves):
        p = [((px + 0.5) / W - 0.5) * W / H * 6, ((py + 0.5) / H - 0.5) * 6]
        s = norm = 0; amp = 1; mg = [1]
        for i in range(octaves):
            s += amp * simplex_noise((p[0] + i * 17.3, p[1] + i * 4.1), mg); norm += amp; amp *= 0.5; p = [p[0] * 2, p[1] * 2]
        return s / norm, mg[0]
    for k in [(12, 9), (150, 12), (20, 85), (140, 80), (100, 40), (47, 61)]: print('simplex 3 octaves', k, field(*k, 3))
    for px, py in [(20, 85), (47, 61), (70, 30), (12, 20)]:
        p = [((px + 0.5) / W - 0.5) * W / H * 6, ((py + 0.5) / H - 0.5) * 6, 0.5]
        print('simplex compare, value noise', (px, py), srgb(value_noise(p, [1])))
    for k in [(140, 80), (100, 40)]: print('simplex compare, simplex', k, srgb(field(*k, 1)[0] * 0.5 + 0.5))

def value_noise_cases():
    for lin in (False, True):
        for px, py in [(12, 9), (150, 12), (20, 85), (140, 80), (100, 40), (47, 61)]:
            p = ((px + 0.5) / 96 * 8, (py + 0.5) / 96 * 8, 0.25)
            i = [math.floor(c) for c in p]; fr = [c - math.floor(c) for c in p]
            f = fr if lin else [fade3(t) for t in fr]
            n = lambda a, b, c: hash_pcg((i[0] + a, i[1] + b, i[2] + c))
            v = mix(mix(mix(n(0, 0, 0), n(1, 0, 0), f[0]), mix(n(0, 1, 0), n(1, 1, 0), f[0]), f[1]),
                    mix(mix(n(0, 0, 1), n(1, 0, 1), f[0]), mix(n(0, 1, 1), n(1, 1, 1), f[0]), f[1]), f[2])
            print('value-noise', 'linear' if lin else 'cubic', (px, py), round(2 * v - 1, 6))

def warped():
    PL = [(-0.85, -0.05), (-0.45, 0.25), (-0.05, -0.10), (0.35, 0.22), (0.80, 0.0), (-0.70, -0.38), (-0.20, -0.30), (0.25, -0.22), (0.70, -0.36)]
    def nearest(p, a, b):
        ab = (b[0] - a[0], b[1] - a[1]); t = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2); t = min(max(t, 0), 1)
        return (a[0] + ab[0] * t, a[1] + ab[1] * t)
    W, H = 320, 180
    for px, py in [(221, 134), (209, 126), (205, 125), (40, 20), (300, 170)]:
        p = (((px + 0.5) / W - 0.5) * W / H, -((py + 0.5) / H - 0.5))
        push = [0, 0]; wsum = 0
        for i in range(8):
            if i + 1 == 5: continue
            q = nearest(p, PL[i], PL[i + 1]); d = (p[0] - q[0], p[1] - q[1]); h = 1 / (1 + (d[0] ** 2 + d[1] ** 2) / 0.05 ** 2) ** 2
            push[0] += d[0] * h * h; push[1] += d[1] * h * h; wsum += h
        q = (p[0] + 2 * push[0] / wsum, p[1] + 2 * push[1] / wsum)
        x = [12 * q[0], 12 * q[1], 0.37]; v = 0; amp = 1
        for i in range(3): v += amp * gradient_noise(x, [1]); x = [c * 2 for c in x]; amp *= 0.5
        t = min(max(0.5 + 0.6 * v, 0), 1)
        print('warped', (px, py), round(v, 6), [round(a + (b - a) * t, 6) for a, b in zip((0.05, 0.07, 0.12), (0.95, 0.85, 0.6))])

if __name__ == '__main__':
    brick(); fbm(); randu_scatter(); simplex(); value_noise_cases(); warped()
