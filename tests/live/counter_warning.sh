#!/bin/sh
# `passlab run` on a graph whose append counter exceeds its buffer's capacity in every frame:
# 10 frames give exactly one warning (once per overflow episode, not per frame) on stderr and
# one counter-overflow event.
# Usage: counter_warning.sh PASSLAB WORKDIR   (from the source folder)
set -eu
passlab=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
xvfb-run -a -s "-screen 0 640x480x24" "$passlab" run tests/bad/counter-overflow --frames 10 --events "$work/events.jsonl" \
  > "$work/run.log" 2>&1
warnings=$(grep -c "warning: buffer 'nodes' counted 192 > capacity 128" "$work/run.log" || true)
events=$(grep -c '"event":"counter-overflow".*"count":192,"capacity":128' "$work/events.jsonl" || true)
frames=$(grep -c '"frame-presented"' "$work/events.jsonl" || true)
if [ "$warnings" != 1 ] || [ "$events" != 1 ] || [ "$frames" != 10 ]; then
  echo "expected 1 warning, 1 event over 10 frames; got $warnings warning(s), $events event(s), $frames frame(s)" >&2
  cat "$work/run.log" >&2
  exit 1
fi
echo "ok: one overflow warning over $frames frames"
