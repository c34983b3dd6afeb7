#!/bin/sh
# Per-preset frame time and per-pass GPU time at one size, as a Markdown table (for issue notes
# and READMEs), then a summary: presets within 33 ms and 16.7 ms per frame, the slowest five,
# the cold start and the single-pass edit-to-frame p95.
# Benchmarks are not tests: nothing here fails on a time.
# Usage: catalogue.sh PASSLAB [SIZE] [FRAMES] [PRESET_DIR ...]
#   catalogue.sh build/default/lab/passlab 640x360 10 presets/shading presets/post
set -eu
passlab=$1 size=${2:-640x360} frames=${3:-10}
shift $(( $# < 3 ? $# : 3 ))
[ $# -gt 0 ] || set -- presets
rows=$(mktemp); trap 'rm -f "$rows"' EXIT
load_before=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
echo "| preset | frame median ms | per-pass GPU median ms |"
echo "| --- | --- | --- |"
for root in "$@"; do
  find "$root" -name preset.toml | sort | while read -r toml; do
    dir=$(dirname "$toml")
    out=$("$passlab" bench "$dir" --size "$size" --frames "$frames" --warmup 2 2>/dev/null) || { echo "| ${dir#presets/} | failed | |"; continue; }
    echo "$out" | awk -v name="${dir#presets/}" '
      /^frame / { for (i = 1; i <= NF; ++i) if ($i == "median") med = $(i + 1) }
      /^pass / { inpass = 1; next }
      inpass && NF >= 3 && $3 == "ms" { p = p (p == "" ? "" : ", ") $1 " " $2 }
      /^json/ { inpass = 0 }
      END { printf "| %s | %s | %s |\n", name, med, p }'
  done
done | tee "$rows"
# The summary (issue #21's targets): how many presets meet 33 ms (30 fps) and 16.7 ms (60 fps)
# per frame, and the slowest five. The load average says how much else the machine was running:
# on a shared 2-core machine medians move by 20% or more between runs.
load_after=$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo "?")
awk -F'|' -v size="$size" -v lb="$load_before" -v la="$load_after" '
  { name = $2; ms = $3; gsub(/ /, "", name); gsub(/ /, "", ms) }
  ms == "failed" { ++failed; next }
  ms ~ /^[0-9.]+$/ { ++n; if (ms + 0 <= 33.0) ++ok30; if (ms + 0 <= 16.7) ++ok60; print ms, name > "/dev/stderr" }
  END {
    printf "\nsummary at %s: %d presets measured, %d <= 33 ms, %d <= 16.7 ms", size, n, ok30, ok60
    if (failed) printf ", %d failed to run", failed
    printf " (load average %s before, %s after)\n", lb, la
  }' "$rows" 2> "$rows.ms"
echo "slowest five:"
sort -rn "$rows.ms" | head -5 | awk '{ printf "  %s %s ms\n", $2, $1 }'
rm -f "$rows.ms"
# The two latencies issue #21 keeps where they are, so a regression shows in the same summary:
# cold start (exec to PNG, fBm, median of 5) and a single-pass edit-to-frame p95 (10 edits of
# tests/live/preset under Xvfb). CATALOGUE_LATENCY=0 leaves them out (no Xvfb, or in a hurry).
if [ "${CATALOGUE_LATENCY:-1}" != 0 ]; then
  here=$(cd "$(dirname "$0")" && pwd)
  cold=$(sh "$here/cold_start.sh" "$passlab" 5 2>/dev/null | awk '/wall, exec to PNG/ { print $NF }')
  echo "cold start (exec to PNG, fBm 640x360, median of 5): ${cold:-failed} ms"
  if command -v xvfb-run > /dev/null; then
    edit=$(sh "$here/reload_latency.sh" "$passlab" 10 2>/dev/null | awk '/^total/ { print $6 }')
    echo "single-pass edit to new frame p95 (10 edits): ${edit:-failed} ms"
  fi
fi
