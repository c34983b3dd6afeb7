#!/bin/sh
# Per-preset frame time and per-pass GPU time at one size, as a Markdown table (for issue notes
# and READMEs). Benchmarks are not tests: nothing here fails on a time.
# Usage: catalogue.sh PASSLAB [SIZE] [FRAMES] [PRESET_DIR ...]
#   catalogue.sh build/default/lab/passlab 640x360 10 presets/shading presets/post
set -eu
passlab=$1 size=${2:-640x360} frames=${3:-10}
shift $(( $# < 3 ? $# : 3 ))
[ $# -gt 0 ] || set -- presets
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
done
