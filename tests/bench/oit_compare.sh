#!/bin/sh
# OIT family comparison (issue 15): every method of presets/oit renders the shared scene at depth
# complexities 2, 8 and 32 (params.stack: k full-screen quads) and the heavy case (the scene's
# quads cut into 102400 triangles, depth complexity 3, with the crossing pair and the cyclic
# pinwheel); each image is compared with per-pixel-linked-lists (the exact, fully sorted
# reference) at 640x360: RMSE and max abs error over RGB; frame median and summed per-pass GPU
# median from `passlab bench`; memory = the bytes of every image and buffer the method declares at
# 640x360 with the row's params (test-only images, `reference` and `dp_*`, not counted).
# Writes the table between the markers in presets/oit/README.md (or prints it with --print).
#
# Every method runs at the same opacity, --alpha (default 0.25: at 0.5 the layers behind the
# fourth show through only 1/16 and every bounded method looks exact).
# Usage: tests/bench/oit_compare.sh [PASSLAB] [--print] [--frames N] [--alpha A]
#   PASSLAB defaults to build/default/lab/passlab; run from the repository root. Takes ~15 min
#   on lavapipe (2 cores): depth peeling at 32 layers is 32 geometry passes of 32 full-screen quads.
set -eu
passlab=build/default/lab/passlab
args=""
for a in "$@"; do case $a in --*|[0-9]*|.[0-9]*) args="$args $a";; *) passlab=$a;; esac; done
exec python3 - "$passlab" $args <<'PY'
import json, math, os, re, struct, subprocess, sys, tempfile, tomllib, zlib

passlab = sys.argv[1]
printonly = '--print' in sys.argv
frames = int(sys.argv[sys.argv.index('--frames') + 1]) if '--frames' in sys.argv else 5
alpha = sys.argv[sys.argv.index('--alpha') + 1] if '--alpha' in sys.argv else '0.25'
W, H = 640, 360
work = tempfile.mkdtemp(prefix='oit-compare-')

# (label, settings) -> params; the reference row is per-pixel-linked-lists with room for every fragment.
SETTINGS = [('heavy', {'heavy': 'true'}, 3), ('2', {'stack': '2'}, 2), ('8', {'stack': '8'}, 8), ('32', {'stack': '32'}, 32)]
def method_params(name, depth):
    return {'alpha': alpha, **own_params(name, depth)}
def own_params(name, depth):
    if name == 'per-pixel-linked-lists': return {'capacity': str(max(depth, 4)), 'max_frags': '32'}
    if name in ('depth-peeling', 'dual-depth-peeling'): return {'layers': str(max(depth, 3))}   # exact: n >= depth
    if name in ('atomic-loop-kbuffer', 'hybrid-atomic-wboit'): return {'k': '4'}               # bounded memory
    return {}
METHODS = ['per-pixel-linked-lists', 'alpha-blend-sorted', 'weighted-blended', 'depth-peeling',
           'dual-depth-peeling', 'atomic-loop-kbuffer', 'hybrid-atomic-wboit', 'colored-blended']
METHODS = [m for m in METHODS if os.path.isfile(f'presets/oit/{m}/preset.toml')]

def read_png(path):
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n', path
    pos, idat, w = 8, b'', 0
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8]); body = data[pos + 8:pos + 8 + n]; pos += 12 + n
        if kind == b'IHDR': w, h, depth, ctype = struct.unpack('>IIBB', body[:10])
        elif kind == b'IDAT': idat += body
    chans = {2: 3, 6: 4, 0: 1, 4: 2}[ctype]; bpp = chans * depth // 8; stride = w * bpp
    raw = zlib.decompress(idat); out = bytearray(); prev = bytearray(stride)
    for y in range(h):
        f = raw[y * (stride + 1)]; line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0; b = prev[i]; c = prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line; prev = line
    scale = 255.0 if depth == 8 else 65535.0
    vals = out if depth == 8 else struct.unpack(f'>{len(out) // 2}H', bytes(out))
    return [[vals[(y * w + x) * chans + c] / scale for c in range(3)] for y in range(h) for x in range(w)]

def render(name, params, tag):
    d = f'{work}/{name}-{tag}'
    cmd = [passlab, 'render', f'presets/oit/{name}', '-o', d, '--size', f'{W}x{H}', '--format', 'png']
    for k, v in params.items(): cmd += ['--set', f'{k}={v}']
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0: return None, r.stderr.strip().splitlines()[-1] if r.stderr else 'failed'
    png = [l for l in r.stdout.split() if l.endswith('.png')][0]
    return read_png(png), None

def bench(name, params):
    j = f'{work}/bench.json'
    cmd = [passlab, 'bench', f'presets/oit/{name}', '--size', f'{W}x{H}', '--frames', str(frames), '--warmup', '2', '--json', j]
    for k, v in params.items(): cmd += ['--set', f'{k}={v}']
    if subprocess.run(cmd, capture_output=True).returncode != 0: return None, None
    b = json.load(open(j))
    return b['frame_ms']['median'], sum(p['gpu_ms_median'] for p in b['passes'])

BPP = {'rgba16f': 8, 'rg32f': 8, 'r16f': 2, 'r32f': 4, 'rgba8': 4, 'd32': 4, 'r32ui': 4, 'rgba32f': 16}
def memory(name, params):
    g = tomllib.load(open(f'presets/oit/{name}/preset.toml', 'rb'))
    pv = {k: (v['value'] if isinstance(v, dict) else v) for k, v in g.get('params', {}).items()}
    for k, v in params.items(): pv[k] = {'true': 1, 'false': 0}.get(v, None) if v in ('true', 'false') else float(v)
    def ev(expr):
        e = expr.replace('view.w', str(W)).replace('view.h', str(H))
        e = re.sub(r'params\.(\w+)', lambda m: str(int(pv[m.group(1)])), e)
        return int(eval(e, {'__builtins__': {}}, {}))
    total = 0
    for n, img in g.get('images', {}).items():
        if n == 'reference' or n.startswith('dp_'): continue
        total += W * H * BPP[img.get('format', 'rgba8')]
    for n, buf in g.get('buffers', {}).items():
        total += buf['size'] if isinstance(buf['size'], int) else ev(buf['size'])
    return total

rows = {}
refs = {}
for label, s, depth in SETTINGS:
    refs[label], err = render('per-pixel-linked-lists', {**s, **method_params('per-pixel-linked-lists', depth)}, label)
    assert refs[label] is not None, err
for name in METHODS:
    for label, s, depth in SETTINGS:
        p = {**s, **method_params(name, depth)}
        img, err = render(name, p, label)
        if img is None: rows[(name, label)] = {'err': err}; continue
        d2, mx = 0.0, 0.0
        for a, b in zip(img, refs[label]):
            for c in range(3): e = abs(a[c] - b[c]); d2 += e * e; mx = max(mx, e)
        fm, gpu = bench(name, p)
        rows[(name, label)] = {'rmse': math.sqrt(d2 / (3 * len(img))), 'max': mx, 'frame': fm, 'gpu': gpu,
                               'mem': memory(name, p), 'params': ' '.join(f'{k}={v}' for k, v in method_params(name, depth).items())}
        print(name, label, rows[(name, label)], file=sys.stderr)

def cell(r):
    if 'err' in r: return 'failed: ' + r['err']
    t = f"{r['frame']:.1f}" if r['frame'] is not None else '-'
    return f"{r['rmse']:.4f} / {r['max']:.3f} / {t} ms / {r['mem'] / 1e6:.1f} MB"
lines = ['| method | ' + ' | '.join(f'heavy (102k tris, depth 3)' if l == 'heavy' else f'depth {l}' for l, _, _ in SETTINGS) + ' |',
         '| --- |' + ' --- |' * len(SETTINGS)]
for name in METHODS:
    lines.append(f'| `{name}` | ' + ' | '.join(cell(rows[(name, l)]) for l, _, _ in SETTINGS) + ' |')
params = [f'`{n}` ' + ', '.join(f'{l}: ' + ' '.join(f'{k}={v}' for k, v in own_params(n, d).items()) for l, _, d in SETTINGS)
          for n in METHODS if any(own_params(n, d) for _, _, d in SETTINGS)]
table = '\n'.join(lines) + '\n\nCells: RMSE / max abs error against per-pixel-linked-lists (RGB, 8-bit PNGs: 1/255 = 0.0039 is the floor) / frame median (`passlab bench`, ' + str(frames) + ' frames) / memory of the method\'s images and buffers. Every method at alpha = ' + alpha + '; other params: ' + '; '.join(params) + '.\n'
if printonly: print(table); sys.exit(0)
readme = 'presets/oit/README.md'
s = open(readme).read()
a, b = '<!-- oit-compare:begin -->', '<!-- oit-compare:end -->'
s = s[:s.index(a) + len(a)] + '\n' + table + s[s.index(b):]
open(readme, 'w').write(s)
print(table)
PY
