#!/usr/bin/env bash
# The README's two commands:
#   scripts/quickstart.sh          install what is missing, build, render the default preset
#   scripts/quickstart.sh test     install what is missing, build, run the whole test suite
# .ci/run calls the second. CI=true builds with warnings as errors.
set -euo pipefail
cd "$(dirname "$0")/.."

mode="${1:-render}"
case "$mode" in render|test) ;; *) echo "usage: $0 [render|test]" >&2; exit 2;; esac

# The test suite also covers `render --video` and looks at the HTML report in a headless
# browser, so it installs ffmpeg and Chromium too (deps.sh --video --browser).
if [ "$mode" = test ]; then scripts/deps.sh --video --browser; else scripts/deps.sh; fi

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
  # The sanitizer stage: the unit tests and the fuzz replays (seeds and every input that once
  # crashed, tests/fuzz/found) again under AddressSanitizer + UBSan, in build/asan; any report
  # fails. PASSLAB_SKIP_SANITIZERS=1 skips it on a machine in a hurry (CI never sets it).
  if [ "${PASSLAB_SKIP_SANITIZERS:-0}" != 1 ]; then
    echo "sanitizer stage: unit tests and fuzz replays under ASan + UBSan (build/asan) ..."
    cmake --preset asan -G Ninja >/dev/null
    cmake --build build/asan -j "$(nproc)" --target \
      test_util test_graph test_shader test_scene test_image test_exec test_check test_mutate test_import test_lab \
      fuzz_preset fuzz_glsl fuzz_import fuzz_mesh fuzz_image fuzz_spirv passlab
    export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
      UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
    ctest --test-dir build/asan -j 2 -L 'unit|fuzz' --output-on-failure --timeout 900
    # Real presets through the sanitized host: one per family (the whole catalogue would double
    # the CI time), every case under the validation layer. A report in a -j worker after its
    # results fails the run too (test_workers.cpp checks each worker's exit against its results).
    sample=""
    for p in aa/msaa ao/ssao bump/normal-mapping deferred/gbuffer-shading envmap/sphere-map \
             fundamentals/textured-cube gi/radiosity image/pull-push npr/hatching oit/weighted-blended \
             particles/billboards post/separable-blur procedural/fbm raytrace/bvh-traversal shading/lambert \
             shadows/pcf texturing/mipmapping visibility/backface-culling volumetric/atmospheric-sky; do
      sample="$sample presets/$p"
    done
    # shellcheck disable=SC2086
    build/asan/lab/passlab test $sample --validation -j 2
  fi
fi
