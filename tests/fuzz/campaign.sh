#!/bin/sh
# A fuzzing campaign (issue #18): builds the fuzz targets with clang, libFuzzer, ASan and UBSan
# (CMake preset `fuzz`, build/fuzz), then runs each target for SECONDS on a copy of its seed
# corpus. Prints per target the executions, the corpus growth and any crash, leak or timeout
# file libFuzzer wrote. A finding is replayed by the ordinary build once copied into
# tests/fuzz/found/<target>/ (ctest fuzz/replay-<target>), after the bug is fixed.
# Usage: campaign.sh [SECONDS per target] [TARGET ...]   (targets: preset glsl import mesh image spirv)
# Needs clang and libclang-rt-14-dev (`scripts/deps.sh --fuzz` installs them).
set -eu
cd "$(dirname "$0")/../.."
secs=${1:-300}; shift $(( $# > 0 ? 1 : 0 ))
[ $# -gt 0 ] || set -- preset glsl import mesh image spirv
cmake --preset fuzz -G Ninja > /dev/null
for t in "$@"; do cmake --build build/fuzz --target "fuzz_$t" -j "$(nproc)"; done
out=build/fuzz/campaign; mkdir -p "$out"
seeds() {  # tests/fuzz/seeds.txt, as the ctest replay reads it: every extension in every folder
  dirs=$(awk -v t="$1" '$1 == t { print $2 }' tests/fuzz/seeds.txt | sort -u)
  exts=$(awk -v t="$1" '$1 == t { print $3 }' tests/fuzz/seeds.txt | sort -u)
  set --
  for e in $exts; do [ $# = 0 ] || set -- "$@" -o; set -- "$@" -name "*$e"; done
  # shellcheck disable=SC2086
  find $dirs -type f \( "$@" \) -size -2M
}
status=0
for t in "$@"; do
  corpus="$out/$t/corpus"; art="$out/$t/findings/"
  rm -rf "$out/$t"; mkdir -p "$corpus" "$art"
  i=0; for f in $(seeds "$t"); do i=$((i + 1)); cp "$f" "$corpus/seed$i"; done
  n0=$(ls "$corpus" | wc -l)
  # -timeout: an input taking 10 s is a hang; -rss_limit_mb: passlab refuses absurd sizes, so
  # an input that needs 2 GB is a finding too.
  rc=0
  ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "build/fuzz/tests/fuzz/fuzz_$t" "$corpus" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 \
      -max_len=65536 -artifact_prefix="$art" -print_final_stats=1 > "$out/$t/log.txt" 2>&1 || rc=$?
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/$t/log.txt" | grep -o '[0-9]*$' || echo "?")
  n1=$(ls "$corpus" | wc -l)
  found=$(ls "$art" | wc -l)
  echo "fuzz_$t: ${secs} s, $execs executions, corpus $n0 -> $n1, findings $found (exit $rc; log $out/$t/log.txt)"
  ls "$art" | sed "s|^|  $art|"
  [ "$found" = 0 ] || status=1
done
exit $status
