#!/bin/sh
# `passlab render` names its files after the preset's folder however the folder is spelt:
# `render .` inside it, a trailing slash or a "..": all write <folder>.png (never "..png").
# Usage: render_names.sh PASSLAB WORKDIR
set -eu
passlab=$(realpath "$1") work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
src=$(pwd)/presets/fundamentals/fullscreen-pass
[ -f "$src/preset.toml" ] || fail "no $src"
(cd "$src" && "$passlab" render . -o "$work/dot" --size 16x16 > "$work/dot.txt" 2>/dev/null)
[ -f "$work/dot/fullscreen-pass.png" ] || fail "render . wrote $(ls -A "$work/dot")"
"$passlab" render "$src/../fullscreen-pass/" -o "$work/dotdot" --size 16x16 > /dev/null 2>&1
[ -f "$work/dotdot/fullscreen-pass.png" ] || fail "render DIR/../fullscreen-pass/ wrote $(ls -A "$work/dotdot")"
"$passlab" render "$src/./preset.toml" -o "$work/file" --size 16x16 > /dev/null 2>&1
[ -f "$work/file/fullscreen-pass.png" ] || fail "render DIR/./preset.toml wrote $(ls -A "$work/file")"
echo "ok"
