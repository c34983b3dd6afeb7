#!/bin/sh
# Live-reload test under Xvfb: starts `passlab run` on a copy of tests/live/preset, then edits
# it the way editors do (write a temporary file, rename it over the original): a shader change,
# a syntax error, its fix, an include change and a TOML change. The event log must show each
# reload with the right outcome, and frames must keep being presented while the shader is
# broken (keep-last-good). Only the passes whose code changed get new pipelines; a param saved
# in the sidecar file is applied at start; --capture saves the window with its panel.
# Usage: live_reload.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cp -r "$here/preset" "$work/p"
p="$work/p" ev="$work/events.jsonl"
printf '# saved by the panel\ngain = 0.75\n' > "$p/preset.params.toml"
save() {  # save FILE CONTENT: temp file + rename, like vim/VS Code/JetBrains
  printf '%s\n' "$2" > "$1.tmp~" && mv "$1.tmp~" "$1"
}
. "$here/lib.sh"   # count, wait_for
# The pid file names passlab itself (exec), so the test can stop it; xvfb-run then ends Xvfb.
xvfb-run -a -s "-screen 0 640x480x24" sh -c 'echo $$ > "$1"; exec "$2" run "$3" --events "$4" --seconds 120' sh \
  "$work/pid" "$passlab" "$p" "$ev" > "$work/run.log" 2>&1 &
runner=$!
trap 'kill "$(cat "$work/pid" 2>/dev/null)" 2>/dev/null || true' EXIT
wait_for '"started"' 1
wait_for frame-presented 3

save "$p/main.frag" '#version 450
#include "tint.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(tint(uv).bgr * params.gain, 1.0);
}'
wait_for reload-ok 1

save "$p/main.frag" '#version 450
#include "tint.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(tint(uv) * params.gain, 1.0) + undefined_name;
}'
wait_for reload-failed 1
n=$(count '"broken":true')
wait_for '"broken":true' $((n + 3))   # frames keep coming from the last good pipeline

save "$p/main.frag" '#version 450
#include "tint.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(tint(uv) * params.gain, 1.0);
}'
wait_for reload-ok 2

save "$p/tint.glsl" 'vec3 tint(vec2 uv) { return vec3(uv.yx, 0.25); }'
wait_for reload-ok 3

sed 's/value = 1.0, min/value = 0.5, min/' "$p/preset.toml" > "$p/preset.toml.tmp~" && mv "$p/preset.toml.tmp~" "$p/preset.toml"
wait_for reload-ok 4
wait_for frame-presented $(( $(count frame-presented) + 2 ))

kill "$(cat "$work/pid")" 2>/dev/null || true
wait "$runner" 2>/dev/null || true
trap - EXIT

fail() { echo "FAIL: $1" >&2; grep -v frame-presented "$ev" >&2; exit 1; }
grep '"reload-failed"' "$ev" | grep -q '"file":"[^"]*main.frag","line":6' || fail "reload-failed does not name main.frag:6"
grep '"reload-failed"' "$ev" | grep -q "undefined_name" || fail "reload-failed does not carry the compiler message"
grep '"reload-started"' "$ev" | grep -q 'tint.glsl' || fail "the include edit was not seen"
grep '"reload-started"' "$ev" | grep -q 'preset.toml' || fail "the TOML edit was not seen"
grep -q '"started".*"sidecar_values":1' "$ev" || fail "the sidecar's saved value was not applied"
# Pipelines are rebuilt for changed code only: main.frag and its include rebuild "main", never
# "post"; the TOML edit changes a param value, which needs no pipeline at all.
oks=$(grep '"reload-ok"' "$ev")
[ "$(echo "$oks" | sed -n 1p | grep -o '"rebuilt":\[[^]]*\]')" = '"rebuilt":["main"]' ] || fail "the shader edit did not rebuild exactly main"
[ "$(echo "$oks" | sed -n 3p | grep -o '"rebuilt":\[[^]]*\]')" = '"rebuilt":["main"]' ] || fail "the include edit did not rebuild exactly main"
[ "$(echo "$oks" | sed -n 4p | grep -o '"rebuilt":\[[^]]*\]')" = '"rebuilt":[]' ] || fail "the param edit rebuilt a pipeline"

# The window with its panel, saved by --capture: a PNG of the window's size, the panel docked
# in a 360-pixel strip left of the 320x200 view (the window grows by the strip). The view must
# show the whole picture, uncovered: the capture's right 320x200 equals a headless render.
xvfb-run -a -s "-screen 0 800x480x24" "$passlab" run "$p" --size 320x200 --frames 3 --capture "$work/ui.png" > "$work/capture.log" 2>&1 ||
  fail "run --capture failed: $(cat "$work/capture.log")"
[ "$(od -An -tx1 -j16 -N8 "$work/ui.png" | tr -d ' \n')" = "000002a8000000c8" ] || fail "the capture is not a 680x200 PNG (360 panel + 320 view)"
"$passlab" render "$p" --size 320x200 --set gain=0.75 -o "$work/headless" > "$work/headless.log" 2>&1 || fail "render failed: $(cat "$work/headless.log")"
python3 "$here/png_region.py" "$work/ui.png" "$(ls "$work"/headless/*.png | head -1)" 360 0 ||
  fail "the view in the window is not the rendered picture (covered by the panel, or offset)"
grep -q 'undefined_name' "$work/run.log" || fail "the terminal did not show the error"
echo "live reload: $(grep -c reload-ok "$ev") reloads ok, $(grep -c reload-failed "$ev") failed as expected, $(grep -c frame-presented "$ev") frames presented"
