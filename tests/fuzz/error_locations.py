#!/usr/bin/env python3
# How often a broken shader's error names file:line:col, only file:line, or no line (issue #18).
# Breaks each of N random single edits (a character deleted or inserted, a name misspelt, a line
# or a ';'/')' removed; seed 7) into a copy of each preset's shaders, runs `passlab check` on
# the copy and classifies the first error line; prints the counts and the messages that lacked a
# column. Usage: error_locations.py N [family/preset ...]. Not a test: a measure for the notes.
import os, random, re, shutil, subprocess, sys, collections, tempfile
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
exe = os.environ.get('PASSLAB', root + '/build/default/lab/passlab')
presets = sys.argv[2:] or ['procedural/fbm', 'post/separable-blur', 'npr/gs-silhouettes', 'fundamentals/tessellation-displacement']
n = int(sys.argv[1])
rng = random.Random(7)
junk = list(';{}()[],.+-*/=<>!&|?:#') + ['vec3', 'float', 'int', 'uniform', 'return', 'xyz', '1.0', 'if', 'else', 'main', 'void', 'layout', 'in', 'out']
def mutate(t):
    k = rng.randrange(5)
    if not t: return t
    p = rng.randrange(len(t))
    if k == 0: return t[:p] + t[p+1:]
    if k == 1: return t[:p] + rng.choice(junk) + t[p:]
    if k == 2:
        ids = [m for m in re.finditer(r'\b[A-Za-z_]\w*\b', t)]
        if not ids: return t
        m = rng.choice(ids); return t[:m.start()] + m.group(0) + 'q' + t[m.end():]
    if k == 3:
        lines = t.split('\n'); i = rng.randrange(len(lines)); del lines[i]; return '\n'.join(lines)
    ws = [m.start() for m in re.finditer(r'[;)]', t)]
    if not ws: return t
    q = rng.choice(ws); return t[:q] + t[q+1:]
stats = collections.Counter(); examples = collections.defaultdict(list)
for pr in presets:
    work = os.path.join(tempfile.mkdtemp(prefix='passlab-errloc-'), 'p')
    shutil.copytree(root + '/presets/' + pr, work, symlinks=True)
    files = [f for f in os.listdir(work) if f.endswith(('.frag', '.vert', '.comp', '.geom', '.tesc', '.tese', '.glsl'))]
    for i in range(n):
        f = os.path.join(work, rng.choice(files)); orig = open(f).read()
        open(f, 'w').write(mutate(orig))
        r = subprocess.run([exe, 'check', work], capture_output=True, text=True, timeout=60)
        open(f, 'w').write(orig)
        if r.returncode == 0: stats['compiled'] += 1; continue
        first = next((l for l in r.stderr.split('\n') if 'error' in l), r.stderr.split('\n')[0])
        if re.match(r'\S+:\d+:\d+: ', first): kind = 'line+col'
        elif re.match(r'\S+:\d+: ', first): kind = 'line only'
        else: kind = 'no line'
        stats[kind] += 1
        if kind != 'line+col': examples[kind].append(first[:200])
    shutil.rmtree(os.path.dirname(work), ignore_errors=True)
print(dict(stats))
for k, v in examples.items():
    c = collections.Counter(re.sub(r"'[^']*'", "'X'", re.sub(r'^\S+?:(\d+:)?\s*', '', e)) for e in v)
    print('==', k)
    for e, m in c.most_common(25): print(m, e)
