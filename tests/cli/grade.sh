#!/bin/sh
# `passlab grade` and `--exercise`: the shipped exercise fails with hints and image paths, the
# reference copy passes, a misspelt file is warned about, a student's compile error points into
# the student's file, and grading or testing an exercise never writes into the preset.
# Usage: grade.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
preset=presets/shading/lambert
n=$(grep -c '^\[\[test\]\]' "$preset/preset.toml")  # the preset's cases (it gains some over time)
before=$(find "$preset" -type f -exec md5sum {} + | sort | md5sum)

# 1. The exercise as shipped (TODOs): every case fails, each with its hint and the image paths.
rc=0; "$passlab" grade shading/lambert --exercise "$preset/exercise" --out "$work/out1" > "$work/g1.txt" 2> "$work/g1.err" || rc=$?
[ "$rc" = 1 ] || fail "the unsolved exercise: exit $rc, expected 1"
grep -q "exercise: using your lambert.frag" "$work/g1.err" || fail "the shadowed file is not named"
grep -q "^FAIL white-furnace" "$work/g1.txt" || fail "white-furnace did not fail"
grep -q "hint: L_o must be 1 everywhere" "$work/g1.txt" || fail "no hint for white-furnace"
grep -q "(yours).*(reference).*(difference)" "$work/g1.txt" || fail "no image paths for the golden"
[ -f "$work/out1/lambert.default.diff.png" ] || fail "no diff image written"
grep -q "grade: 0 of $n cases pass" "$work/g1.txt" || fail "wrong summary"

# 2. A solution (the reference's own shader) passes every case.
mkdir "$work/solved"; cp "$preset/lambert.frag" "$work/solved/"
"$passlab" grade shading/lambert --exercise "$work/solved" --out "$work/out2" > "$work/g2.txt" 2>&1 || fail "the reference copy does not pass: $(cat "$work/g2.txt")"
grep -q "grade: $n of $n cases pass" "$work/g2.txt" || fail "the reference copy: wrong summary"

# 3. A misspelt file name shadows nothing: a warning, not silence.
mkdir "$work/typo"; cp "$preset/lambert.frag" "$work/typo/lambret.frag"
# It shadows nothing, so nothing is graded (it would grade the reference): exit 1, naming the
# files the exercise asks for. An empty folder too.
rc=0; "$passlab" grade shading/lambert --exercise "$work/typo" --out "$work/out3" > "$work/g3.txt" 2> "$work/g3.err" || rc=$?
grep -q "warning: lambret.frag shadows no file the preset reads" "$work/g3.err" || fail "no warning for a misspelt file"
[ "$rc" = 1 ] || fail "a folder shadowing nothing: exit $rc, expected 1"
grep -q "grade: nothing graded: .* holds none of the files this exercise asks for (lambert.frag)" "$work/g3.txt" || fail "no 'nothing graded': $(cat "$work/g3.txt")"
mkdir "$work/empty"
rc=0; "$passlab" grade shading/lambert --exercise "$work/empty" --out "$work/out3" > "$work/g3b.txt" 2>&1 || rc=$?
[ "$rc" = 1 ] && grep -q "nothing graded" "$work/g3b.txt" || fail "an empty exercise folder: exit $rc: $(cat "$work/g3b.txt")"

# 4. A compile error in the student's copy is reported at its file:line:col.
mkdir "$work/broken"; sed 's/vec3 lo = vec3(0.0);/vec3 lo = vec3(0.0)/' "$preset/exercise/lambert.frag" > "$work/broken/lambert.frag"
rc=0; "$passlab" grade shading/lambert --exercise "$work/broken" --out "$work/out4" > "$work/g4.txt" 2> "$work/g4.err" || rc=$?
[ "$rc" = 1 ] || fail "a broken exercise: exit $rc, expected 1"
grep -q "broken/lambert.frag:1[0-9]:[0-9]*: error" "$work/g4.err" || fail "the compile error does not point into the student's file: $(cat "$work/g4.err")"

# 5. --exercise on test and run-less verbs; a missing folder is a usage error.
"$passlab" test "$preset" --exercise "$work/solved" > /dev/null 2>&1 || fail "test --exercise with the solution failed"
rc=0; "$passlab" check "$preset" --exercise "$work/nope" > /dev/null 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "a missing exercise folder: exit $rc, expected 2"

after=$(find "$preset" -type f -exec md5sum {} + | sort | md5sum)
[ "$before" = "$after" ] || fail "grading wrote into the preset folder"
echo "passlab grade: 5 cases passed"
