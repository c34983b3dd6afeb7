#!/bin/sh
# Every presets/<family>/<name>/exercise/ folder is a working exercise: as shipped (with its
# TODOs) `passlab grade` fails, and with the reference's own files in its place it passes. So an
# exercise can neither be solved already nor refer to a file the preset does not have.
# Usage: exercises.sh PASSLAB WORKDIR [FAMILY]   (FAMILY: only presets/FAMILY; ctest runs one per family)
set -eu
passlab=$1 work=$2 family=${3:-}
rm -rf "$work"; mkdir -p "$work"
n=0 nm=0
for ex in $(find "presets${family:+/$family}" -type d -name exercise | sort); do
  preset=$(dirname "$ex")
  name=$(echo "$preset" | tr / _)
  rc=0; "$passlab" grade "$preset" --exercise "$ex" --out "$work/$name.todo" > "$work/$name.todo.txt" 2>&1 || rc=$?
  [ "$rc" = 1 ] || { echo "FAIL: $ex as shipped: exit $rc, expected 1 (an exercise must not pass untouched)" >&2; cat "$work/$name.todo.txt" >&2; exit 1; }
  # The solution: each exercise file replaced by the reference file of the same relative name,
  # from the preset folder or else from passes/.
  sol="$work/$name.solution"; mkdir -p "$sol"
  for f in $(cd "$ex" && find . -type f ! -name '*.md' ! -name '*.txt'); do
    if [ -f "$preset/$f" ]; then ref="$preset/$f"; elif [ -f "passes/$f" ]; then ref="passes/$f"; else
      echo "FAIL: $ex/$f has no reference file in $preset or passes/" >&2; exit 1; fi
    mkdir -p "$sol/$(dirname "$f")"; cp "$ref" "$sol/$f"
  done
  "$passlab" grade "$preset" --exercise "$sol" --out "$work/$name.sol" > "$work/$name.sol.txt" 2>&1 ||
    { echo "FAIL: $ex with the reference files does not pass" >&2; cat "$work/$name.sol.txt" >&2; exit 1; }
  # Plausible wrong solutions (mistakes/<name>/: the exercise's files with one classic error,
  # plus expect.txt holding a line the output must contain, normally part of the hint of the
  # case that catches it). Each must fail, and fail with that hint, so a hint is seen to lead.
  if [ -d "$preset/mistakes" ]; then
    for m in "$preset"/mistakes/*/; do
      m=${m%/}; mname=$(basename "$m")
      [ -f "$m/expect.txt" ] || { echo "FAIL: $m has no expect.txt" >&2; exit 1; }
      rc=0; "$passlab" grade "$preset" --exercise "$m" --out "$work/$name.$mname" > "$work/$name.$mname.txt" 2>&1 || rc=$?
      [ "$rc" = 1 ] || { echo "FAIL: mistake $m: exit $rc, expected 1 (the cases do not catch it)" >&2; cat "$work/$name.$mname.txt" >&2; exit 1; }
      want=$(head -n 1 "$m/expect.txt")
      grep -qF -- "$want" "$work/$name.$mname.txt" ||
        { echo "FAIL: mistake $m fails without the expected hint: $want" >&2; cat "$work/$name.$mname.txt" >&2; exit 1; }
      nm=$((nm + 1))
    done
  fi
  n=$((n + 1))
done
[ "$n" -gt 0 ] || { echo "FAIL: no exercise folders found in presets${family:+/$family}" >&2; exit 1; }
echo "exercises${family:+ ($family)}: $n graded (each fails as shipped and passes with the reference); $nm mistakes each caught with its hint"
