#!/bin/sh
# The GI family's comparison (presets/gi/README.md): every compared method renders its `radiance`
# image (linear, direct + indirect, the shared Cornell box of passes/gi/cornell.glsl from the shared
# view camera) at 320x180, and this script measures it against the path-traced reference:
#   - RMSE of `radiance` over all pixels and the RGB channels;
#   - RMSE of the indirect part alone, where both the method and the reference declare an
#     `indirect` image (else "n/a");
#   - the reference's own noise, estimated as the RMSE between two halves of its sample budget
#     (frames N/2 with two seeds is not available, so: the RMSE between N/2 and N frames, which
#     bounds how far below it a method's RMSE can be trusted);
#   - the frame median and the GPU time (sum of the per-pass medians) from `passlab bench` at the
#     default 640x360 view.
# A method whose folder does not exist yet gets a row saying so. EXRs are read with the standard
# library (tests/bench/exr.py: passlab writes ZIP-compressed float EXRs through OpenImageIO).
#
# Usage: tests/bench/gi_compare.sh [PASSLAB] [--write]
#   PASSLAB   the passlab binary (default build/default/lab/passlab)
#   --write   replace the table between the markers in presets/gi/README.md (else: stdout)
# Environment: GI_REF (default presets/gi/path-tracing-reference) the reference preset,
#   GI_REF_FRAMES (default 256) its frames, GI_REF_SET (default "interleave=1 spp=4") its params, GI_SIZE (default 320x180), GI_BENCH_FRAMES (default 30).
# Run from the repository root. Not a ctest: the reference takes minutes on llvmpipe.
set -eu
passlab=${1:-build/default/lab/passlab}
write=${2:-}
[ -x "$passlab" ] || { echo "gi_compare.sh: no passlab at $passlab (build first, or pass its path)" >&2; exit 2; }
exec python3 - "$passlab" "$write" <<'PY'
import json, math, os, subprocess, sys, tempfile
sys.path.insert(0, os.path.join("tests", "bench"))
from exr import read_exr

passlab, write = sys.argv[1], sys.argv[2] == "--write"
METHODS = ["instant-radiosity", "reflective-shadow-maps", "imperfect-shadow-maps", "radiance-hints"]
# Frames a method needs for the picture it shows live: radiance hints refine a running mean of
# RSM samples for rh_frames (32) frames and then keep it; the others are complete in one frame.
METHOD_FRAMES = {"radiance-hints": 32}
ref = os.environ.get("GI_REF", "presets/gi/path-tracing-reference")
ref_frames = int(os.environ.get("GI_REF_FRAMES", "256"))
# The reference's params: every pixel traced every frame (interleave 1) at 4 paths a frame, so
# frames x 4 = paths per pixel (the live default traces one pixel in 64 per frame).
ref_sets = os.environ.get("GI_REF_SET", "interleave=1 spp=4").split()
size = os.environ.get("GI_SIZE", "320x180")
bench_frames = os.environ.get("GI_BENCH_FRAMES", "30")
tmp = tempfile.mkdtemp(prefix="gi-compare-")

def run(args):
    p = subprocess.run([passlab] + args, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"gi_compare.sh: passlab {' '.join(args)} failed:\n{p.stdout}{p.stderr}")
    return p.stdout

def images_of(preset):
    return {i["name"] for i in json.loads(run(["check", preset, "--json", "-"]))["images"]}

def render(preset, images, frames=1, tag="", sets=()):
    """{image: (w, h, pixels)} of `images` rendered at `size`."""
    out = os.path.join(tmp, os.path.basename(preset.rstrip("/")) + tag)
    args = ["render", preset, "-o", out, "--size", size, "--frames", str(frames), "--format", "exr", "--timeout", "900"]
    for a in sets:
        args += ["--set", a]
    for im in images:
        args += ["--pass", im]
    files = run(args).split()
    # each --pass image is written as <preset>.<image>.exr (also when it is the output)
    return {im: read_exr(next(f for f in files if f.endswith("." + im + ".exr"))) for im in images}

def rmse(a, b):
    (w, h, pa), (w2, h2, pb) = a, b
    if (w, h) != (w2, h2):
        raise SystemExit(f"gi_compare.sh: sizes differ ({w}x{h} vs {w2}x{h2})")
    s = sum((p[c] - q[c]) ** 2 for p, q in zip(pa, pb) for c in range(3))
    return math.sqrt(s / (3 * len(pa)))

def mean(a):
    return sum(p[c] for p in a[2] for c in range(3)) / (3 * len(a[2]))

def bench(preset):
    j = os.path.join(tmp, os.path.basename(preset) + ".bench.json")
    run(["bench", preset, "--frames", bench_frames, "--json", j])
    d = json.load(open(j))
    return d["frame_ms"]["median"], sum(p["gpu_ms_median"] for p in d["passes"]), d["device"]

if not os.path.isdir(ref):
    raise SystemExit(f"gi_compare.sh: no reference preset at {ref} (set GI_REF)")
ref_images = images_of(ref)
want = ["radiance"] + (["indirect"] if "indirect" in ref_images else [])
print(f"reference {ref}: {ref_frames} frames at {size} ...", file=sys.stderr)
R = render(ref, want, ref_frames, sets=ref_sets)
R_half = render(ref, ["radiance"], ref_frames // 2, "-half", sets=ref_sets)
noise = rmse(R["radiance"], R_half["radiance"])

rows, device = [], ""
for m in METHODS:
    d = os.path.join("presets", "gi", m)
    if not os.path.isdir(d):
        rows.append(f"| {m} | — | — | — | — | — | not built yet (no {d}) |")
        print(f"{m}: skipped, {d} does not exist", file=sys.stderr)
        continue
    imgs = images_of(d)
    if "radiance" not in imgs:
        rows.append(f"| {m} | — | — | — | — | — | declares no `radiance` image |")
        continue
    print(f"{m} ...", file=sys.stderr)
    both = "indirect" in imgs and "indirect" in R
    M = render(d, ["radiance"] + (["indirect"] if both else []), METHOD_FRAMES.get(m, 1))
    e = rmse(M["radiance"], R["radiance"])
    ei = f"{rmse(M['indirect'], R['indirect']):.4f}" if both else "n/a"
    ratio = mean(M["radiance"]) / max(mean(R["radiance"]), 1e-12)
    frame, gpu, device = bench(d)
    frames = METHOD_FRAMES.get(m, 1)
    rows.append(f"| {m} | {e:.4f} | {ei} | {ratio:.3f} | {frame:.1f} | {gpu:.1f} | {f'after {frames} frames' if frames > 1 else ''} |")

table = "\n".join([
    f"Measured by `tests/bench/gi_compare.sh` against `{ref}` ({ref_frames} frames, {size}); the",
    f"reference's own noise (RMSE between {ref_frames // 2} and {ref_frames} frames) is {noise:.4f}; reference mean",
    f"radiance {mean(R['radiance']):.4f}. Times: `passlab bench` at 640x360, {device}.",
    "",
    "| method | RMSE radiance | RMSE indirect | mean / reference mean | frame median ms | GPU ms (sum of passes) | note |",
    "| --- | --- | --- | --- | --- | --- | --- |",
] + rows)
if write:
    path = "presets/gi/README.md"
    text = open(path).read()
    a, b = "<!-- gi-compare:begin -->", "<!-- gi-compare:end -->"
    if a not in text or b not in text:
        raise SystemExit(f"gi_compare.sh: {path} lacks the markers {a} ... {b}")
    text = text[:text.index(a) + len(a)] + "\n" + table + "\n" + text[text.index(b):]
    open(path, "w").write(text)
    print(f"wrote the table into {path}", file=sys.stderr)
else:
    print(table)
PY
