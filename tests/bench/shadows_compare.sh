#!/bin/sh
# The shadows family's comparison table (presets/shadows/README.md), measured on this machine:
# for every preset under presets/shadows/ it runs `passlab test -v` (the invariants, with their
# measured figures) and `passlab bench` at 640x360 (frame median), and reads the shadow storage
# from preset.toml. Methods of the catalogue (docs/catalogue.md 3.11) without a preset yet get a row
# saying so; they fill in when their folder exists.
#
# Usage: tests/bench/shadows_compare.sh [PASSLAB] [--write]
#   PASSLAB  the passlab binary (default build/default/lab/passlab)
#   --write  replace the table between the markers in presets/shadows/README.md (else: stdout)
# Run from the repository root. Needs python3 (3.11: tomllib). Not a ctest: it takes minutes.
set -eu
passlab=${1:-build/default/lab/passlab}
write=${2:-}
[ -x "$passlab" ] || { echo "shadows_compare.sh: no passlab at $passlab (build first, or pass its path)" >&2; exit 2; }
exec python3 - "$passlab" "$write" <<'PY'
import glob, os, re, subprocess, sys, tomllib

passlab, write = sys.argv[1], sys.argv[2] == "--write"
# The catalogue's methods, in its order; a preset's folder name is its key.
CATALOGUE = ["shadow-map", "pcf", "gaussian-pcf", "cascaded-shadow-maps", "sdsm", "omni-cube-shadows",
             "dual-paraboloid-shadows", "stencil-shadow-volumes", "planar-projected", "blob-shadows", "baked-soft-shadows"]
DEPTH_BYTES = {"d16": 2, "d32": 4, "d24s8": 4, "d32s8": 8}

def run(args):
    p = subprocess.run([passlab] + args, capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr

def cases(out):
    """[(name, passed, [detail lines])] from `passlab test -v`."""
    res = []
    for line in out.splitlines():
        m = re.match(r"(PASS|FAIL) \S+: (\S+) \(", line)
        if m:
            res.append((m.group(2), m.group(1) == "PASS", []))
        elif res and re.match(r"\s+(ok|FAIL)\s", line):
            res[-1][2].append(line.strip())
    return res

def figure(detail):
    """The measured part of one check line, condensed."""
    d = re.sub(r"^(ok|FAIL)\s+", "", detail)
    m = re.search(r"(\d+) of (\d+) pixel\(s\)[^(]*\(([\d.e-]+)\)", d)
    if m:
        extra = re.search(r"max difference ([\d.e+-]+)", d)
        n, total = int(m.group(1)), int(m.group(2))
        share = f"{n}/{total} px ({100 * n / total:.3f}%)"
        return share + (f", max diff {float(extra.group(1)):.3g}" if extra else "")
    m = re.search(r"host (min|max|sum) over (\d+) pixel\(s\) = ([^;]+); buffer holds ([^,]+), error ([^ ]+)", d)
    if m:
        return f"{m.group(1)} {m.group(3)} = host, error {m.group(5)}"
    m = re.search(r"probe buffer '(\w+)'\[(\d+)\].*: got ([^,]+)", d)
    if m:
        return f"{m.group(1)}[{m.group(2)}] = {m.group(3)}"
    m = re.search(r"values in \[([^\]]+)\]", d)
    if m:
        return f"values in [{m.group(1)}]"
    m = re.search(r"(\d+ of \d+ group\(s\) out of order)", d)
    if m:
        return m.group(1)
    m = re.search(r"rmse ([\d.e-]+)", d)
    if m:
        return f"rmse {float(m.group(1)):.3g}"
    return d[:60]

def size_of(expr, params, view=(640, 360)):
    if isinstance(expr, int):
        return expr, expr
    if isinstance(expr, list):
        return expr[0], expr[1]
    e = str(expr)
    if e == "view":
        return view
    m = re.fullmatch(r"params\.(\w+)", e)
    if m:
        v = params[m.group(1)]
        v = v["value"] if isinstance(v, dict) else v
        return int(v), int(v)
    return None

def storage(toml):
    """Shadow storage: depth-format images not at the view size (maps, cascades, cubes), at the
    params' defaults; the view's own depth buffer is not counted."""
    total, parts = 0, []
    for name, img in toml.get("images", {}).items():
        fmt = img.get("format", "")
        if fmt not in DEPTH_BYTES or img.get("size", "view") == "view":
            continue
        wh = size_of(img["size"], toml.get("params", {}))
        if not wh:
            parts.append(f"{name}: size {img['size']}?")
            continue
        layers = 6 if img.get("kind") == "cube" else img.get("layers", 1)
        b = wh[0] * wh[1] * layers * DEPTH_BYTES[fmt]
        total += b
        parts.append(f"{name} {wh[0]}²{'x' + str(layers) if layers > 1 else ''} {fmt}")
    return (f"{total / 2**20:.1f} MiB ({', '.join(parts)})" if parts else "no depth map")

rows, details = [], []
load = open("/proc/loadavg").read().split()[0] if os.path.exists("/proc/loadavg") else "?"
present = {os.path.basename(os.path.dirname(p)): p for p in glob.glob("presets/shadows/*/preset.toml")}
for name in CATALOGUE + sorted(set(present) - set(CATALOGUE)):
    if name not in present:
        rows.append(f"| `{name}` | not built yet | | | | |")
        continue
    toml = tomllib.load(open(present[name], "rb"))
    folder = os.path.dirname(present[name])
    _, out = run(["test", folder, "-v"])
    cs = cases(out)
    passed = sum(1 for c in cs if c[1])
    def fig(case_prefix):
        hits = [c for c in cs if c[0].startswith(case_prefix)]
        label = lambda c: c[0][len(case_prefix):].lstrip("-")
        return "; ".join((f"{label(c)}: " if label(c) else "") + figure(c[2][-1]) for c in hits if c[2]) or "—"
    _, b = run(["bench", folder, "--size", "640x360", "--frames", "16"])
    m = re.search(r"frame\s+min ([\d.]+) ms, median ([\d.]+) ms", b)
    ms = f"{float(m.group(2)):.1f} (min {float(m.group(1)):.1f})" if m else "?"
    rows.append(f"| `{name}` | {fig('agrees-with-ray-traced')} | {fig('acne-free')} | {fig('contact')} | {ms} | {storage(toml)} |"
                f" {passed}/{len(cs)} |")
    details.append(f"- `{name}`: " + "; ".join(
        f"{c[0]} {'✓' if c[1] else '✗'} " + ", ".join(figure(d) for d in c[2] if "golden" not in d) for c in cs))

table = ["| method | ray-traced agreement outside edge bands | unoccluded plane lit (acne) | contact line (Peter Panning) | frame ms, 640x360: median (min) | shadow storage | cases passed |",
         "| --- | --- | --- | --- | --- | --- | --- |"]
# The header has 7 columns; rows of absent methods pad to it.
table += [r if r.count("|") == 8 else r + " |" for r in rows]
text = "\n".join(table) + "\n\nMeasured by every case (`passlab test -v`):\n\n" + "\n".join(details) + \
       f"\n\n(lavapipe, load average {load} when measured; frame times move with the other jobs on the 2 cores.)\n"
if not write:
    print(text)
    sys.exit(0)
readme = "presets/shadows/README.md"
src = open(readme).read()
a, b = "<!-- shadows_compare:begin -->", "<!-- shadows_compare:end -->"
if a not in src or b not in src:
    sys.exit(f"shadows_compare.sh: {readme} has no {a} ... {b} markers")
open(readme, "w").write(src[: src.index(a) + len(a)] + "\n" + text + src[src.index(b):])
print(f"wrote the table into {readme}")
PY
