#!/bin/sh
# `passlab run` on a graph whose append counter exceeds its buffer's capacity (3 layers into
# room for 2): one warning per overflow episode, not per frame. Many overflowing frames give one
# warning (and one counter-overflow event); an edit to 1 layer ends the episode, an edit back to 3
# starts a second one: exactly two in all.
# Usage: counter_warning.sh PASSLAB WORKDIR   (from the source folder)
set -eu
passlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work/p"
p="$work/p" ev="$work/events.jsonl"
src=$(pwd)/tests/bad/counter-overflow
sed "s|\.\./\.\./graphs/buffer-checks/append.frag|$(pwd)/tests/graphs/buffer-checks/append.frag|" "$src/preset.toml" > "$p/preset.toml"
. "$(dirname "$0")/lib.sh"   # count, wait_for
layers() {  # layers N: rewrite the param the way editors save (temp file + rename)
  sed "s/^layers = .*/layers = $1/" "$p/preset.toml" > "$p/preset.toml.tmp~" && mv "$p/preset.toml.tmp~" "$p/preset.toml"
}
xvfb-run -a -s "-screen 0 640x480x24" sh -c 'echo $$ > "$1"; exec "$2" run "$3" --events "$4" --seconds 60' sh \
  "$work/pid" "$passlab" "$p" "$ev" > "$work/run.log" 2>&1 &
trap 'kill "$(cat "$work/pid" 2>/dev/null)" 2>/dev/null || true' EXIT
wait_for '"counter-overflow"' 1
n=$(count frame-presented)
wait_for frame-presented $((n + 10))          # ten more overflowing frames: no second warning
[ "$(count '"counter-overflow"')" = 1 ] || { echo "warned more than once in one episode" >&2; exit 1; }
layers 1
wait_for reload-ok 1
n=$(count frame-presented)
wait_for frame-presented $((n + 3))           # within capacity: the episode ends
layers 3
wait_for reload-ok 2
wait_for '"counter-overflow"' 2               # a new episode warns again
n=$(count frame-presented)
wait_for frame-presented $((n + 10))
kill "$(cat "$work/pid")" 2>/dev/null || true
sleep 0.5
warnings=$(grep -c "warning: buffer 'nodes' counted 192 > capacity 128" "$work/run.log" || true)
events=$(count '"counter-overflow".*"count":192,"capacity":128')
if [ "$warnings" != 2 ] || [ "$events" != 2 ]; then
  echo "expected 2 warnings and 2 events (two episodes); got $warnings warning(s), $events event(s)" >&2
  cat "$work/run.log" >&2
  exit 1
fi
echo "ok: one warning per overflow episode ($(count frame-presented) frames, 2 episodes)"
