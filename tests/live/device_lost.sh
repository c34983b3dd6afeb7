#!/bin/sh
# A lost Vulkan device in the live lab (on a GPU: a driver reset after a runaway shader), here
# simulated (PASSLAB_SIMULATE_DEVICE_LOST=N: the N-th fence wait reports VK_ERROR_DEVICE_LOST):
# the lab logs device-lost, recreates the device, window and panel, rebuilds the graph and goes
# on presenting; the picture after it equals a headless render, and the exit code is 0. A second
# run loses the device every 20th wait: three recoveries, then the lab gives up (exit 1).
# Usage: device_lost.sh PASSLAB WORKDIR
set -eu
passlab=$(realpath "$1") work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
p="$here/viewer"
rc=0
PASSLAB_SIMULATE_DEVICE_LOST=25 PASSLAB_VALIDATION=1 xvfb-run -a -s "-screen 0 800x480x24" \
  "$passlab" run "$p" --size 320x200 --frames 60 --capture "$work/after.png" --events "$work/events.jsonl" > "$work/run.log" 2>&1 || rc=$?
[ "$rc" = 0 ] || fail "the lab exited $rc after a device loss: $(cat "$work/run.log")"
grep -q '"event":"device-lost"' "$work/events.jsonl" || fail "no device-lost event: $(cat "$work/run.log")"
grep -q '"event":"device-recreated"' "$work/events.jsonl" || fail "no device-recreated event"
after=$(sed -n '/"event":"device-recreated"/,$p' "$work/events.jsonl" | grep -c '"event":"frame-presented"' || true)
[ "$after" -ge 10 ] || fail "only $after frames presented after the device came back"
! grep -qi "validation error" "$work/run.log" || fail "validation errors around the recovery: $(grep -i 'validation error' "$work/run.log" | head -3)"
"$passlab" render "$p" --size 320x200 -o "$work/headless" > "$work/headless.log" 2>&1 || fail "render failed: $(cat "$work/headless.log")"
python3 "$here/png_region.py" "$work/after.png" "$(ls "$work"/headless/*.png | head -1)" 360 0 ||
  fail "the picture after the recovery is not the rendered one"
# Lost again and again (every 20th wait): three recoveries, then the lab gives up, exit 1.
rc=0
PASSLAB_SIMULATE_DEVICE_LOST=20+ xvfb-run -a -s "-screen 0 800x480x24" \
  "$passlab" run "$p" --size 320x200 --frames 400 --events "$work/again.jsonl" > "$work/again.log" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "four losses: exit $rc, expected 1: $(tail -3 "$work/again.log")"
[ "$(grep -c '"event":"device-recreated"' "$work/again.jsonl")" = 3 ] || fail "not three recoveries before giving up"
grep -q "lost 4 times in this session: giving up" "$work/again.log" || fail "no give-up message: $(tail -3 "$work/again.log")"
echo "device lost: recovered (frames after: $after), picture equals the headless render"
