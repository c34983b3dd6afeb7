#!/usr/bin/env bash
# The README's two commands:
#   scripts/quickstart.sh          install what is missing, build, render the default preset
#   scripts/quickstart.sh test     install what is missing, build, run the whole test suite
# .ci/run calls the second. CI=true builds with warnings as errors.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-render}"
case "$mode" in render|test) ;; *) echo "usage: $0 [render|test]" >&2; exit 2;; esac

scripts/deps.sh

preset=default
if [ "${CI:-}" = "true" ]; then preset=ci; fi
build_dir=build/default
cmake --preset "$preset" -G Ninja >/dev/null
cmake --build "$build_dir" -j "$(nproc)"

if [ "$mode" = render ]; then
  out="${PASSLAB_OUT:-out}"
  echo "rendering the default preset (presets/procedural/fbm) headlessly into $out/ ..."
  "$build_dir/lab/passlab" render presets/procedural/fbm -o "$out"
else
  # Every test runs under the Khronos validation layer; any validation message fails it.
  ctest --test-dir "$build_dir" -j 2 --output-on-failure --timeout 600
fi
