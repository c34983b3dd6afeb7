#!/bin/sh
# `passlab new`: the copy is complete and works, --with-passes shadows the library, and an
# existing destination is refused without touching it (passlab never overwrites user files).
# Usage: new_preset.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }

# 1. A plain copy of a preset that reads passes/ files: every file of its folder, and it checks.
"$passlab" new "$work/blur" --from post/separable-blur > "$work/out1.txt"
src=presets/post/separable-blur
for f in $(cd "$src" && find . -type f ! -name preset.params.toml); do
  cmp -s "$src/$f" "$work/blur/$f" || fail "$f was not copied verbatim"
done
"$passlab" check "$work/blur" > /dev/null 2>&1 || fail "the copy does not pass check"
grep -q "next: passlab run" "$work/out1.txt" || fail "no hint printed"

# 2. An existing destination: exit 2 and nothing written into it.
mkdir "$work/taken"; echo mine > "$work/taken/notes.txt"
rc=0; "$passlab" new "$work/taken" --from post/separable-blur > /dev/null 2> "$work/err2.txt" || rc=$?
[ "$rc" = 2 ] || fail "existing destination: exit $rc, expected 2"
grep -q "already exists" "$work/err2.txt" || fail "existing destination: no clear message"
[ "$(ls "$work/taken")" = notes.txt ] && [ "$(cat "$work/taken/notes.txt")" = mine ] || fail "existing destination was modified"

# 3. --with-passes: the library files the preset reads are copied at their relative path and
#    shadow passes/ (an edit of the copy changes the copy's render, not the library).
"$passlab" new "$work/bloom" --from post/bloom --with-passes > "$work/out3.txt"
[ -f "$work/bloom/post/gauss17.glsl" ] || fail "--with-passes did not copy post/gauss17.glsl"
cmp -s passes/post/gauss17.glsl "$work/bloom/post/gauss17.glsl" || fail "post/gauss17.glsl differs"
"$passlab" check "$work/bloom" > /dev/null 2>&1 || fail "the --with-passes copy does not pass check"
printf 'this is not glsl\n' >> "$work/bloom/post/gauss17.glsl"
rc=0; "$passlab" check "$work/bloom" > /dev/null 2> "$work/err3.txt" || rc=$?
[ "$rc" = 1 ] || fail "an edit of the shadowing copy was not picked up (exit $rc)"
grep -q "$work/bloom/post/gauss17.glsl\|bloom/post/gauss17.glsl" "$work/err3.txt" || fail "the error does not point at the local copy"
"$passlab" check presets/post/bloom > /dev/null 2>&1 || fail "the library was affected"

# 4. A broken or unknown source writes nothing.
rc=0; "$passlab" new "$work/none" --from no-such-preset > /dev/null 2>&1 || rc=$?
[ "$rc" != 0 ] && [ ! -e "$work/none" ] || fail "unknown source: exit $rc, or a folder was created"

echo "passlab new: 4 cases passed"
