#!/bin/sh
# Convergence of presets/gi/path-tracing-reference, measured: renders the Cornell box at N =
# 4, 8, ..., 256 paths per pixel and a long reference (8192 spp by default, its own seed, so it
# shares no path with the renders it judges), computes the RMSE of each against it over every
# pixel and RGB channel, fits the slope of log RMSE over log N by least squares and writes
# the plot (an SVG) into the preset folder. Monte Carlo's error is sigma / sqrt(N): slope -0.5.
#
# Usage: tests/bench/pt_convergence.sh [PASSLAB] [--quick] [--write]
#   PASSLAB  the passlab binary (default build/default/lab/passlab; /work/bin/passlab works with
#            PASSLAB_ROOT set to this tree)
#   --quick  32x18, N = 4..64, a 2048-spp reference (the ctest entry, ~20 s)
#   --write  write presets/gi/path-tracing-reference/convergence.svg (else only print)
# Renders get a 600 s frame watchdog (a loaded machine stretches a 0.3 s frame past the default 20 s).
# Exits 1 when the slope is outside -0.5 +- 0.1. Run from the repository root; python3 stdlib only.
set -eu
passlab=${1:-build/default/lab/passlab}
shift || true
[ -x "$passlab" ] || { echo "pt_convergence.sh: no passlab at $passlab (build first, or pass its path)" >&2; exit 2; }
exec python3 - "$passlab" "$@" <<'PY'
import math, os, subprocess, sys, tempfile, time
sys.path.insert(0, os.path.join("tests", "bench"))
import exr_read

passlab, flags = sys.argv[1], sys.argv[2:]
quick, write = "--quick" in flags, "--write" in flags
PRESET = "presets/gi/path-tracing-reference"
size, counts, ref_spp = ("32x18", [4, 8, 16, 32, 64], 2048) if quick else ("64x36", [4, 8, 16, 32, 64, 128, 256], 8192)
PER_FRAME = 32  # paths per pixel per frame; llvmpipe's 65535-iteration loop limit allows ~100

def render(spp, seed, out):
    per = min(spp, PER_FRAME)
    args = [passlab, "render", PRESET, "--size", size, "--frames", str(spp // per), "--set", "interleave=1",
            "--set", "spp=%d" % per, "--set", "seed=%d" % seed, "--pass", "radiance", "--format", "exr", "--timeout", "600", "-o", out]
    t = time.time()
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("render failed: %s\n%s" % (" ".join(args), p.stdout + p.stderr))
    w, h, v = exr_read.read(os.path.join(out, "path-tracing-reference.radiance.exr"))
    return [x for c in "RGB" for x in v[c]], time.time() - t

tmp = tempfile.mkdtemp(prefix="pt-convergence-")
ref, t_ref = render(ref_spp, 1, os.path.join(tmp, "ref"))
print("reference: %s, %d spp, seed 1: %.1f s" % (size, ref_spp, t_ref))
rows = []
for n in counts:
    img, t = render(n, 0, os.path.join(tmp, "n%d" % n))
    rmse = math.sqrt(sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref))
    rows.append((n, rmse))
    print("N = %4d spp: RMSE %.5f  (%.1f s)" % (n, rmse, t))
xs = [math.log(n) for n, _ in rows]
ys = [math.log(r) for _, r in rows]
mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
print("slope of log RMSE over log N: %.3f (expected -0.5 +- 0.1)" % slope)

if write:
    W, H, L, R, T, B = 480, 320, 64, 16, 24, 48
    x0, x1 = math.log(counts[0] / 1.5), math.log(counts[-1] * 1.5)
    lo, hi = math.floor(math.log10(min(r for _, r in rows) / 1.5)), math.ceil(math.log10(max(r for _, r in rows) * 1.5))
    y0, y1 = lo * math.log(10), hi * math.log(10)
    X = lambda v: L + (math.log(v) - x0) / (x1 - x0) * (W - L - R)
    Y = lambda v: T + (y1 - math.log(v)) / (y1 - y0) * (H - T - B)
    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (W, H),
         '<rect width="100%" height="100%" fill="white"/>',
         '<rect x="%d" y="%d" width="%d" height="%d" fill="none" stroke="#888"/>' % (L, T, W - L - R, H - T - B)]
    for n in counts:
        s.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (X(n), T, X(n), H - B))
        s.append('<text x="%.1f" y="%d" text-anchor="middle">%d</text>' % (X(n), H - B + 14, n))
    for e in range(lo, hi + 1):
        v = 10.0 ** e
        s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, Y(v), W - R, Y(v)))
        s.append('<text x="%d" y="%.1f" text-anchor="end">1e%d</text>' % (L - 4, Y(v) + 4, e))
    c = math.exp(my - slope * mx)  # the fit: RMSE = c N^slope
    s.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#c33" stroke-width="1.5"/>' %
             (X(counts[0]), Y(c * counts[0] ** slope), X(counts[-1]), Y(c * counts[-1] ** slope)))
    c5 = rows[0][1] * counts[0] ** 0.5  # the ideal -0.5 through the first point
    s.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#36c" stroke-dasharray="4 3"/>' %
             (X(counts[0]), Y(c5 * counts[0] ** -0.5), X(counts[-1]), Y(c5 * counts[-1] ** -0.5)))
    for n, r in rows:
        s.append('<circle cx="%.1f" cy="%.1f" r="3.5" fill="#c33"/>' % (X(n), Y(r)))
    s.append('<text x="%d" y="%d" text-anchor="middle">paths per pixel N (log)</text>' % ((L + W - R) / 2, H - 14))
    s.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">RMSE vs. %d spp (log)</text>' % ((T + H - B) / 2, (T + H - B) / 2, ref_spp))
    s.append('<text x="%d" y="%d" fill="#c33">measured, fitted slope %.3f</text>' % (L + 10, T + 16, slope))
    s.append('<text x="%d" y="%d" fill="#36c">N^-0.5</text>' % (L + 10, T + 30))
    s.append('<text x="%d" y="16" text-anchor="middle">path-tracing-reference, Cornell box %s</text>' % ((L + W - R) / 2, size))
    s.append('</svg>')
    path = os.path.join(PRESET, "convergence.svg")
    open(path, "w").write("\n".join(s) + "\n")
    print("wrote", path)
sys.exit(0 if abs(slope + 0.5) <= 0.1 else 1)
PY
