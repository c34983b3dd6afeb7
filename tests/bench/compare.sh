#!/bin/sh
# Host vs floor: renders the fBm pass with `passlab bench` (tests/bench/fbm-only, a fragment
# pass, and tests/bench/fbm-compute, the same field by a compute pass) and with the raw-Vulkan
# floor on the SPIR-V passlab generates for each, then prints the throughput ratio host/floor
# (1.0 = no host overhead; the target is >= 0.95).
# Usage: compare.sh PASSLAB FLOOR [SIZE ...] [FRAMES]   e.g. compare.sh build/default/lab/passlab build/default/tests/bench/passlab_floor 640x360 1920x1080 60
set -eu
passlab=$1 floor=$2
shift 2
frames=60
sizes=""
for a in "$@"; do
  case "$a" in *x*) sizes="$sizes $a";; *) frames=$a;; esac
done
[ -n "$sizes" ] || sizes="640x360 1920x1080"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/fragment" "$tmp/compute"
"$passlab" check tests/bench/fbm-only --spirv "$tmp/fragment" --no-cache >/dev/null
"$passlab" check tests/bench/fbm-compute --spirv "$tmp/compute" --no-cache >/dev/null
median() { awk '{for (i = 1; i <= NF; ++i) if ($i == "median") print $(i + 1)}' | tr -d ','; }
# This VM's speed drifts by 10-30% over seconds, so one host run against one floor run can
# read anywhere from 0.75 to 1.2. Alternate host and floor ROUNDS times (default 5) and report
# the median of each and the median of the per-round ratios.
rounds=${ROUNDS:-5}
med() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
for variant in fragment compute; do
  for size in $sizes; do
    w=${size%x*} h=${size#*x}
    : > "$tmp/h" ; : > "$tmp/f"; : > "$tmp/r"
    r=0
    while [ $r -lt "$rounds" ]; do
      if [ $variant = fragment ]; then
        host=$("$passlab" bench tests/bench/fbm-only --size "$size" --frames "$frames" --warmup 5 2>/dev/null | awk '/^frame/ {print $6}')
        base=$("$floor" "$tmp/fragment/fbm.vertex.spv" "$tmp/fragment/fbm.fragment.spv" "$w" "$h" $((frames + 5)) | median)
      else
        host=$("$passlab" bench tests/bench/fbm-compute --size "$size" --frames "$frames" --warmup 5 2>/dev/null | awk '/^frame/ {print $6}')
        base=$("$floor" --compute "$tmp/compute/fbm.compute.spv" "$w" "$h" $((frames + 5)) | median)
      fi
      echo "$host" >> "$tmp/h"; echo "$base" >> "$tmp/f"
      awk -v f="$base" -v h="$host" 'BEGIN { printf "%.4f\n", f / h }' >> "$tmp/r"
      r=$((r + 1))
    done
    range=$(sort -n "$tmp/r" | awk 'NR == 1 {lo = $1} {hi = $1} END {printf "%.3f-%.3f", lo, hi}')
    echo "fbm $variant $size: host median $(med < "$tmp/h") ms, floor median $(med < "$tmp/f") ms, throughput host/floor $(med < "$tmp/r") (rounds $rounds, range $range)"
  done
done
