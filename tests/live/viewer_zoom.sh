#!/bin/sh
# The image viewer under Xvfb: `--inspect cells` opens it on an 8x8 image (fitted: 25 pixels a
# texel in the 320x200 view); one wheel step at view point (200, 100) zooms about that point and
# snaps to a whole power of two (25 * 2 = 50 -> 64 pixels a texel), so the texel under the cursor
# (5, 4) stays under it: in the capture, its square spans view x 162..225 and y 100..163.
# Usage: viewer_zoom.sh PASSLAB WORKDIR   (needs xdotool, installed by scripts/deps.sh)
set -eu
passlab=$(realpath "$1") work=$2
here=$(cd "$(dirname "$0")" && pwd)
command -v xdotool > /dev/null || { echo "FAIL: xdotool is missing (scripts/deps.sh installs it)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
cat > "$work/inside.sh" <<'INNER'
set -eu
passlab=$1 preset=$2 work=$3
"$passlab" run "$preset" --inspect cells --frames 100000 --seconds 60 --events "$work/events.jsonl" > "$work/run.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
i=0; until grep -q frame-presented "$work/events.jsonl" 2>/dev/null; do i=$((i+1)); [ $i -lt 300 ] || exit 1; sleep 0.1; done
w=$(xdotool search --sync --onlyvisible --name "passlab")
xdotool windowfocus --sync "$w"
frames() { grep -c frame-presented "$work/events.jsonl"; }
xdotool mousemove --window "$w" 560 100           # the strip is 360 wide: view point (200, 100)
n=$(frames); i=0; while [ "$(frames)" -lt $((n + 3)) ]; do i=$((i+1)); [ $i -lt 300 ] || exit 1; sleep 0.1; done
xdotool click 4                                   # one wheel step up, with the cursor there
# The lab reads the cursor when it takes the wheel step: leave it there for a few frames.
n=$(frames); i=0; while [ "$(frames)" -lt $((n + 3)) ]; do i=$((i+1)); [ $i -lt 300 ] || exit 1; sleep 0.1; done
xdotool mousemove --window "$w" 100 300           # over the panel: no texel tooltip on the view
n=$(frames); i=0; while [ "$(frames)" -lt $((n + 3)) ]; do i=$((i+1)); [ $i -lt 300 ] || exit 1; sleep 0.1; done
xdotool key F12
i=0; until grep -q "window captured" "$work/run.log"; do i=$((i+1)); [ $i -lt 100 ] || exit 1; sleep 0.1; done
INNER
cd "$work"
xvfb-run -a -s "-screen 0 800x480x24" sh "$work/inside.sh" "$passlab" "$here/viewer" "$work" || { echo "FAIL: the lab did not run" >&2; cat "$work/run.log" >&2; exit 1; }
[ -f passlab-window-1.png ] && [ -f passlab-screenshot-1.png ] || { echo "FAIL: F12 did not write both files: $(ls)" >&2; exit 1; }
python3 - "$here/png_region.py" passlab-window-1.png <<'PY'
import importlib.util, sys
spec = importlib.util.spec_from_file_location("png_region", sys.argv[1]); m = importlib.util.module_from_spec(spec); spec.loader.exec_module(m)
w, h, ch, rows = m.read_png(sys.argv[2])
strip = 360  # the docked panel's strip: view x = window x - 360
def at(x, y): return tuple(rows[y][(strip + x) * ch:(strip + x) * ch + 3])
def edges(values):  # indices where the colour changes from the previous one
    return [i for i in range(1, len(values)) if values[i] != values[i - 1]]
assert (w, h) == (680, 200), (w, h)
row = [at(x, 90) for x in range(320)]      # above the cursor: texel row 3
col = [at(170, y) for y in range(200)]     # left of it: texel column 5
ex, ey = edges(row), edges(col)
print("column edges along y=90:", ex, " row edges along x=170:", ey)
# 64 pixels a texel, texel (5, 4) at view x 161.6..225.6, y 100..164 (positions rounded).
fail = []
if not any(abs(e - 162) <= 1 for e in ex) or not any(abs(e - 226) <= 1 for e in ex): fail.append("texel column 5 is not at x 162..226")
if not any(abs(e - 100) <= 1 for e in ey) or not any(abs(e - 164) <= 1 for e in ey): fail.append("texel row 4 is not at y 100..164")
if any(b - a not in (63, 64, 65) for a, b in zip(ex, ex[1:])): fail.append("texels are not 64 pixels wide: %s" % ex)
# Red grows with x and green with y (cells.frag): the squares are the image's texels in order.
if not at(190, 130)[0] > at(150, 130)[0]: fail.append("red does not grow to the right")
if not at(170, 130)[1] > at(170, 90)[1]: fail.append("green does not grow downwards")
if fail: sys.exit("FAIL: " + "; ".join(fail))
PY
echo "viewer zoom: one wheel step at (200, 100) -> 64 px texels, texel (5, 4) stays under the cursor"
