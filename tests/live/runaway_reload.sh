#!/bin/sh
# An endless (here: very long) loop saved into a running lab: the watchdog (--timeout 2) cuts the
# frame, the lab says in one line that this driver cannot cancel the shader, logs a terminal
# `ended` event with the reason, and exits 1 within seconds, never hanging on the busy device.
# Usage: runaway_reload.sh PASSLAB WORKDIR
set -eu
passlab=$(realpath "$1") work=$2
src=$(cd "$(dirname "$0")/../bad/runaway-test" && pwd)
rm -rf "$work" && mkdir -p "$work/p"
fail() { echo "FAIL: $1" >&2; exit 1; }
cp "$src/main.frag" "$work/p/"
sed -n '/^\[\[test\]\]/q;p' "$src/preset.toml" > "$work/p/preset.toml"
cat > "$work/inside.sh" <<'INNER'
set -u
passlab=$1 work=$2
"$passlab" run "$work/p" --timeout 2 --seconds 60 --events "$work/events.jsonl" > "$work/run.log" 2>&1 &
pid=$!
i=0; until grep -q frame-presented "$work/events.jsonl" 2>/dev/null; do i=$((i+1)); [ $i -lt 300 ] || { kill $pid; exit 3; }; sleep 0.1; done
# Saved the way editors do: a new file renamed over the old one.
sed 's/^iterations = 1$/iterations = 60000/' "$work/p/preset.toml" > "$work/p/.preset.toml.tmp"
mv "$work/p/.preset.toml.tmp" "$work/p/preset.toml"
i=0; while kill -0 $pid 2>/dev/null; do i=$((i+1)); [ $i -lt 300 ] || { kill -9 $pid; exit 4; }; sleep 0.1; done
wait $pid; echo "rc=$?" > "$work/rc"
INNER
xvfb-run -a -s "-screen 0 800x480x24" sh "$work/inside.sh" "$passlab" "$work" || fail "the lab did not start or did not end within 30 s: $(cat "$work/run.log")"
[ "$(cat "$work/rc")" = "rc=1" ] || fail "exit $(cat "$work/rc"), expected 1: $(cat "$work/run.log")"
grep -q '"event":"ended".*"reason":"runaway"' "$work/events.jsonl" || fail "no terminal ended/runaway event: $(tail -3 "$work/events.jsonl")"
grep -q "did not finish within 2.000 s" "$work/run.log" || fail "the watchdog's message is missing: $(cat "$work/run.log")"
grep -q "this driver cannot cancel it: the lab ends" "$work/run.log" || fail "no one-line explanation"
echo "runaway reload: watchdog, one-line explanation, ended event, exit 1"
