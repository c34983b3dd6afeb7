#!/bin/sh
# The warm-up process (lab/warm_up.hpp) under Xvfb, on tests/bench/ten-pass: an edit of the
# include the ten passes share reaches the `passlab warm-up-server` companion, which renders the
# later half of the changed passes (p5..p9) without error; an edit that only touches p0 warms
# nothing beyond it; a GLSL error is not sent (the lab keeps its last good frame); `--warm-up
# off` starts no companion. What is checked is that the
# mechanism runs and what it renders, not its time (tests/bench/reload_latency.sh measures that).
# Usage: warm_up.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cp -r "$here/../bench/ten-pass" "$work/p"
p="$work/p" ev="$work/events.jsonl"
wait_s=30 && . "$here/lib.sh"   # count, wait_for (30 s each)
edit() {  # edit FILE SED: temp file + rename, like an editor
  sed "$2" "$1" > "$1.tmp~" && mv "$1.tmp~" "$1"
}
xvfb-run -a -s "-screen 0 640x480x24" sh -c 'echo $$ > "$1"; exec "$2" run "$3" --events "$4" --seconds 120 --warm-up on' sh \
  "$work/pid" "$passlab" "$p" "$ev" > "$work/run.log" 2>&1 &
trap 'kill "$(cat "$work/pid" 2>/dev/null)" 2>/dev/null || true' EXIT
wait_for frame-presented 3
wait_for warm-up-done 1   # the first build, which the companion learns (and warms)
salt=$$
edit "$p/shared.glsl" "s|/\*KNOB\*/[0-9.]*|/*KNOB*/2.$salt|"
wait_for warm-up-done 2
last=$(grep warm-up-done "$ev" | tail -1)
echo "$last" | grep -q '"passes":\["p5","p6","p7","p8","p9"\]' || { echo "include edit: expected p5..p9 warmed: $last" >&2; exit 1; }
echo "$last" | grep -q '"error":""' || { echo "include edit: the warm-up failed: $last" >&2; exit 1; }
grep -q '"event":"warm-up","t_ms":[0-9.]*,"wall_ms":[0-9.]*,"sent":true' "$ev" || { echo "no warm-up was sent" >&2; exit 1; }
wait_for first_after_reload 1
# Only p0's code changes (first.frag): one changed pass, and half of one is none.
sleep 0.5
edit "$p/first.frag" 's|^void main|// touched\nvoid main|'
wait_for warm-up-done 3
last=$(grep warm-up-done "$ev" | tail -1)
echo "$last" | grep -q '"passes":\[\]' || { echo "p0 edit: expected nothing warmed: $last" >&2; exit 1; }
# A syntax error: nothing is sent (only a build that compiled is warmed), the lab keeps
# presenting its last good frame.
wait_for first_after_reload 2
sleep 0.5
edit "$p/shared.glsl" 's|vec3 shade|vec3 shade(|'
wait_for reload-failed 1
n=$(count frame-presented); wait_for frame-presented $((n + 3))
[ "$(count '"event":"warm-up"')" = 2 ] || { echo "broken include: a warm-up was sent" >&2; exit 1; }
kill "$(cat "$work/pid")" 2>/dev/null || true
sleep 0.5
# --warm-up off: no companion, no warm-up events.
rm -f "$ev"
xvfb-run -a -s "-screen 0 640x480x24" sh -c 'echo $$ > "$1"; exec "$2" run "$3" --events "$4" --frames 5 --warm-up off' sh \
  "$work/pid" "$passlab" "$p" "$ev" > "$work/run-off.log" 2>&1 || true
[ "$(count '"warm-up')" = 0 ] || { echo "--warm-up off still warmed" >&2; exit 1; }
echo "warm-up: include edit warmed p5..p9, a one-pass edit nothing, a broken include not sent; off: none"
