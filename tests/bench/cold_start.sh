#!/bin/sh
# Cold start of `passlab render PRESET -o DIR --size 640x360`: wall time from exec to the PNG on
# disk, over N runs, split into its phases. The process phase (exec, dynamic loading, static
# initialisation up to main) is the external wall time minus the total passlab measures from
# main; the others come from render's own timing line: build (parse, include expansion, glslang
# or the SPIR-V cache, reflection), device (instance + device), setup (resources, pipelines),
# frames (the render incl. llvmpipe's first-draw shader compile), write (readback + PNG encode).
# Usage: cold_start.sh PASSLAB [RUNS] [PRESET] [extra render args, e.g. --no-cache]
set -eu
passlab=$1 runs=${2:-10} preset=${3:-presets/procedural/fbm}
shift $(( $# < 3 ? $# : 3 ))
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
i=0
while [ $i -lt "$runs" ]; do
  t0=$(date +%s%N)
  "$passlab" render "$preset" -o "$out" --size 640x360 "$@" > /dev/null 2> "$out/log"
  t1=$(date +%s%N)
  line=$(grep '^render:' "$out/log")
  echo "$(( (t1 - t0) / 1000 )) $line"
  i=$((i + 1))
done | awk '
  function grab(key,   s) { s = $0; sub(".*" key " ", "", s); sub(" ms.*", "", s); return s + 0 }
  function med(a, n,   i, j, t) { for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
                                   return a[int((n + 1) / 2)] }
  { n++; wall[n] = $1 / 1000; tot[n] = grab("total"); build[n] = grab("build"); dev[n] = grab("device"); setup[n] = grab("setup")
    frames[n] = grab("frames"); write[n] = grab("write"); proc[n] = wall[n] - tot[n] }
  END {
    printf "cold start over %d runs (medians, ms)\n", n
    printf "  process start + loading %7.1f\n  build (parse+compile)   %7.1f\n  device                  %7.1f\n", med(proc, n), med(build, n), med(dev, n)
    printf "  setup (resources+pipes) %7.1f\n  first frame             %7.1f\n  encode (readback+PNG)   %7.1f\n", med(setup, n), med(frames, n), med(write, n)
    printf "  wall, exec to PNG       %7.1f\n", med(wall, n)
  }'
