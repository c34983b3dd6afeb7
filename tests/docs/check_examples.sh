#!/bin/sh
# Extracts every ```toml block of docs/format.md into its own folder as preset.toml and runs
# `passlab check` on it; a failure names the block's first line in docs/format.md.
# Usage: check_examples.sh PASSLAB DOC OUT_DIR
set -u
passlab=$1 doc=$2 out=$3
[ -f "$doc" ] || { echo "$doc does not exist" >&2; exit 1; }
rm -rf "$out" && mkdir -p "$out"
# awk writes each block to OUT/example-<first line>/preset.toml.
awk -v out="$out" '
  /^```toml/ { inblock = 1; start = NR + 1; dir = out "/example-" start; system("mkdir -p " dir); next }
  /^```/ && inblock { inblock = 0; close(dir "/preset.toml"); next }
  inblock { print > (dir "/preset.toml") }
' "$doc"
count=0 failed=0
for dir in "$out"/example-*; do
  [ -d "$dir" ] || continue
  count=$((count + 1))
  if ! err=$("$passlab" check "$dir" 2>&1 >/dev/null); then
    failed=$((failed + 1))
    echo "docs/format.md:${dir##*-}: the example does not pass passlab check:" >&2
    echo "$err" >&2
  fi
done
[ "$count" -gt 0 ] || { echo "no toml examples found in $doc" >&2; exit 1; }
echo "$count examples checked, $failed failed"
[ "$failed" -eq 0 ]
