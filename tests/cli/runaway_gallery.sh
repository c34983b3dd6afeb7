#!/bin/sh
# `passlab gallery` with a runaway preset among others: the runaway costs its own thumbnail
# (reported with the pass), the presets after it still render on a fresh device, exit 1.
# Usage: runaway_gallery.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work/root/presets/a/runaway" "$work/root/presets/b/quick"
fail() { echo "FAIL: $1" >&2; exit 1; }
src=tests/bad/runaway-test
cp "$src/main.frag" "$work/root/presets/a/runaway/"
cp "$src/main.frag" "$work/root/presets/b/quick/"
# The same preset, without its tests: runaway by default in a/, quick in b/.
sed -n '/^\[\[test\]\]/q;p' "$src/preset.toml" | sed 's/^iterations = 1$/iterations = 60000/' > "$work/root/presets/a/runaway/preset.toml"
sed -n '/^\[\[test\]\]/q;p' "$src/preset.toml" > "$work/root/presets/b/quick/preset.toml"
rc=0; PASSLAB_ROOT="$work/root" "$passlab" gallery -o "$work/out" --timeout 2 > "$work/out.txt" 2> "$work/err.txt" || rc=$?
[ "$rc" = 1 ] || fail "exit $rc, expected 1: $(cat "$work/err.txt")"
grep -q "did not finish within 2.000 s" "$work/err.txt" || fail "the runaway is not reported: $(cat "$work/err.txt")"
grep -q "passes in the frame: main" "$work/err.txt" || fail "the runaway pass is not named"
[ -f "$work/out/other-quick.png" ] || fail "the preset after the runaway was not rendered: $(ls "$work/out")"
[ ! -f "$work/out/other-runaway.png" ] || fail "the runaway preset has a thumbnail"
grep -q "contact-sheet.png" "$work/out.txt" || fail "no contact sheet"
echo "ok: runaway reported, the next preset rendered on a fresh device"
