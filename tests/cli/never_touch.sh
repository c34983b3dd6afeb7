#!/bin/sh
# User files are never touched: every verb runs on a copy of a preset tree (its files hashed,
# and every entry listed, before and after), and the tree must be unchanged afterwards. The
# documented writes into a preset are the params sidecar (the live lab's panel), goldens under
# `test --update`, and a missing golden that `test` writes locally (not with --ci); none of
# them happens here, so any change is a failure that names the verb.
# Usage: never_touch.sh PASSLAB WORKDIR
set -eu
passlab=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") work=$2
rm -rf "$work"; mkdir -p "$work/root/presets/shading"
cp -r presets/shading/lambert "$work/root/presets/shading/"
cp -r passes "$work/root/"  # the shader library: hashed too
tree="$work/root"
p="$tree/presets/shading/lambert"
fail() { echo "FAIL: $1" >&2; exit 1; }
state() { (cd "$tree" && find . -print | LC_ALL=C sort && find . -type f -exec md5sum {} + | LC_ALL=C sort) | md5sum; }
before=$(state)
cd "$work"  # outputs that default to the working directory (test-failures/, grade-out/) go here
verb() {  # verb NAME EXPECTED_EXIT ARGS...: runs passlab, then checks the tree
  name=$1 want=$2; shift 2
  rc=0; PASSLAB_ROOT="$work/root" "$@" > "$work/$name.log" 2>&1 || rc=$?
  [ "$rc" = "$want" ] || fail "$name: exit $rc, expected $want: $(tail -5 "$work/$name.log")"
  [ "$(state)" = "$before" ] || fail "$name changed the preset tree"
  echo "ok: $name"
}
verb render 0 "$passlab" render "$p" -o "$work/out" --pass hdr
verb render-exr 0 "$passlab" render "$p" -o "$work/out" --format exr
verb test 0 "$passlab" test "$p" --ci
verb check 0 "$passlab" check "$p"
verb check-spirv 0 "$passlab" check "$p" --spirv "$work/spv"
verb bench 0 "$passlab" bench "$p" --frames 3 --warmup 1 --json "$work/bench.json"
verb gallery 0 "$passlab" gallery -o "$work/gallery" --width 64
verb grade 1 "$passlab" grade "$p" --exercise "$p/exercise" --out "$work/grade"
verb test-exercise 1 "$passlab" test "$p" --exercise "$p/exercise"
verb graph 0 "$passlab" graph "$p" --dot
if command -v xvfb-run > /dev/null; then
  verb run 0 xvfb-run -a -s "-screen 0 640x480x24" "$passlab" run "$p" --frames 5 --capture "$work/run.png"
fi
echo "ok: no verb changed the preset tree"
