#!/bin/sh
# The docked panel under Xvfb: the window opens as the view plus the panel's 360-pixel strip;
# Tab hides the panel by shrinking the window to the view, and shows it again by growing it, so
# the view keeps its size and the graph is never rebuilt for it (no "resize" event).
# Usage: panel_dock.sh PASSLAB WORKDIR   (needs xdotool, installed by scripts/deps.sh)
set -eu
passlab=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
command -v xdotool > /dev/null || { echo "FAIL: xdotool is missing (scripts/deps.sh installs it)" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
cat > "$work/inside.sh" <<'INNER'
set -eu
passlab=$1 preset=$2 work=$3
"$passlab" run "$preset" --size 320x200 --seconds 30 --events "$work/events.jsonl" > "$work/run.log" 2>&1 &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
i=0; until grep -q frame-presented "$work/events.jsonl" 2>/dev/null; do i=$((i+1)); [ $i -lt 200 ] || exit 1; sleep 0.1; done
w=$(xdotool search --sync --onlyvisible --name "passlab")
size() { xdotool getwindowgeometry "$w" | sed -n 's/.*Geometry: //p'; }
settle() {  # settle SIZE: until the window has SIZE (5 s max), then a few frames more
  i=0; while [ "$(size)" != "$1" ]; do i=$((i+1)); [ $i -lt 50 ] || break; sleep 0.1; done
  sleep 0.5; size
}
echo "start $(size)" > "$work/sizes"
xdotool windowfocus --sync "$w"; xdotool key Tab
echo "hidden $(settle 320x200)" >> "$work/sizes"
xdotool key Tab
echo "shown $(settle 680x200)" >> "$work/sizes"
INNER
xvfb-run -a -s "-screen 0 800x480x24" sh "$work/inside.sh" "$passlab" "$here/preset" "$work" || { echo "FAIL: the lab did not start" >&2; cat "$work/run.log" >&2; exit 1; }
fail() { echo "FAIL: $1" >&2; cat "$work/sizes" >&2; exit 1; }
grep -qx "start 680x200" "$work/sizes" || fail "the window did not open as the 320x200 view plus the 360-pixel panel"
grep -qx "hidden 320x200" "$work/sizes" || fail "Tab did not shrink the window to the view"
grep -qx "shown 680x200" "$work/sizes" || fail "Tab did not grow the window back by the panel"
! grep -q '"resize"' "$work/events.jsonl" || fail "showing or hiding the panel rebuilt the graph (a resize event)"
echo "panel dock: $(tr '\n' ';' < "$work/sizes")"
