#!/bin/sh
# Edit-to-new-frame latency of `passlab run` under Xvfb: N edits of a shader by atomic rename;
# for each, detect = reload-started - edit, rebuild = reload-ok - reload-started (parse,
# compile, pipelines), first frame = the next frame-presented - reload-ok (includes llvmpipe's
# shader compilation at first draw), and the warm-up process's job time (lab/warm_up.hpp; it runs
# beside the rebuild and the first frame). Prints p50/p95 of each and of the total.
# PASSLAB_RUN_ARGS adds flags to `passlab run` (e.g. "--warm-up off" for the comparison).
# The edited file holds the token /*KNOB*/1.0; each edit writes a different number there, so
# the generated code really changes (an unused constant would hit Mesa's shader cache). The
# numbers differ between runs too (a per-run salt): Mesa's on-disk cache keeps compiled shaders
# across processes, and a repeated run would otherwise measure cache hits.
# Usage: reload_latency.sh PASSLAB [EDITS] [PRESET_DIR FILE]
#   reload_latency.sh build/default/lab/passlab 20                                 single pass
#   reload_latency.sh build/default/lab/passlab 20 tests/bench/ten-pass shared.glsl  include of 10 passes
set -eu
passlab=$1 edits=${2:-20} src=${3:-$(dirname "$0")/../live/preset} file=${4:-main.frag}
work=$(mktemp -d)
cp -r "$src" "$work/p"
ev="$work/events.jsonl"
xvfb-run -a -s "-screen 0 640x480x24" sh -c 'echo $$ > "$1"; exec "$2" run "$3" --events "$4" --seconds 300 ${PASSLAB_RUN_ARGS:-}' sh \
  "$work/pid" "$passlab" "$work/p" "$ev" > "$work/run.log" 2>&1 &
trap 'kill "$(cat "$work/pid" 2>/dev/null)" 2>/dev/null || true; rm -rf "$work"' EXIT
count() { c=$(grep -c "$1" "$ev" 2>/dev/null) || c=0; echo "${c:-0}"; }
i=0; while [ "$(count frame-presented)" -lt 5 ]; do i=$((i+1)); [ $i -lt 300 ] || exit 1; sleep 0.1; done
shader="$work/p/$file"
grep -q '/\*KNOB\*/' "$shader" || { echo "$file has no /*KNOB*/ token" >&2; exit 2; }
: > "$work/edits"
salt=$(( $(date +%s%N | cut -c8-13) % 9000 + 1000 ))  # 4 digits
k=1
while [ $k -le "$edits" ]; do
  sed "s|/\*KNOB\*/[0-9.]*|/*KNOB*/$k.$salt|" "$shader" > "$shader.tmp~"
  before=$(count first_after_reload)
  date +%s%3N >> "$work/edits"
  mv "$shader.tmp~" "$shader"
  # Wait for the first frame drawn with the new code, then let the lab settle, so that an edit
  # never lands while the previous reload's frame (llvmpipe compiling at first draw) is still
  # running: that would count the previous reload's time as this one's detection.
  i=0; while [ "$(count first_after_reload)" -le "$before" ]; do i=$((i+1)); [ $i -lt 500 ] || { echo "no reload" >&2; exit 1; }; sleep 0.02; done
  sleep 0.3
  k=$((k + 1))
done
awk -v edits="$work/edits" '
  function pct(a, n, p,   i, j, t) { for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
                                     return a[int(p * (n - 1) + 0.5) + 1] }
  function field(line, key,   s) { s = line; sub(".*\"" key "\":", "", s); sub("[,}].*", "", s); return s + 0 }
  BEGIN { n = 0; while ((getline l < edits) > 0) edit[++n] = l + 0 }
  /"reload-started"/ { started[++ns] = field($0, "wall_ms") }
  /"reload-ok"/ { ok[++no] = field($0, "wall_ms"); want_frame = no }
  /"warm-up-done"/ && ns > 0 { warm[++nw] = field($0, "ms") }
  /"frame-presented"/ && want_frame { frame[want_frame] = field($0, "wall_ms"); want_frame = 0 }
  END {
    for (k = 1; k <= n; ++k) { d[k] = started[k] - edit[k]; r[k] = ok[k] - started[k]; f[k] = frame[k] - ok[k]; t[k] = frame[k] - edit[k] }
    printf "edits %d\n", n; if (ENVIRON["VERBOSE"] != "") for (k = 1; k <= n; ++k) printf "  edit %2d: detect %6.1f rebuild %6.1f first frame %6.1f total %6.1f\n", k, d[k], r[k], f[k], t[k]
    printf "detect       p50 %6.1f ms  p95 %6.1f ms\n", pct(d, n, 0.5), pct(d, n, 0.95)
    printf "rebuild      p50 %6.1f ms  p95 %6.1f ms  (parse, compile, pipelines)\n", pct(r, n, 0.5), pct(r, n, 0.95)
    printf "first frame  p50 %6.1f ms  p95 %6.1f ms  (render incl. first-draw compile, present)\n", pct(f, n, 0.5), pct(f, n, 0.95)
    if (nw > 0) printf "warm-up      p50 %6.1f ms  p95 %6.1f ms  (%d jobs of the warm-up process, each from receiving the compiled build, beside the first frame)\n", pct(warm, nw, 0.5), pct(warm, nw, 0.95), nw
    else printf "warm-up      none (--warm-up off, or a GPU)\n"
    printf "total        p50 %6.1f ms  p95 %6.1f ms\n", pct(t, n, 0.5), pct(t, n, 0.95)
  }' "$ev"
