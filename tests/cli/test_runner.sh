#!/bin/sh
# `passlab test` as CI and a new user meet it: nothing tested is a failure, --case selects (and
# an unknown name is an error with a suggestion), outputs that cannot be written exit 3, failed
# goldens leave actual/expected/diff under a path unique per preset, golden writes are always
# printed and counted, --junit/--json carry every case, -j and shards give the same results.
# Usage: test_runner.sh PASSLAB WORKDIR
set -eu
# The cases below are what a developer sees locally (a missing golden is written, not failed),
# so the CI=true of the CI run must not leak into them.
unset CI
passlab=$(realpath "$1") work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
expect_rc() { # expect_rc CODE LOG CMD...: runs CMD, output into LOG, and checks the exit code
  want=$1 log=$2; shift 2
  rc=0; "$@" > "$log" 2>&1 || rc=$?
  [ "$rc" = "$want" ] || fail "$* exited $rc, expected $want: $(cat "$log")"
}
src=presets/fundamentals/fullscreen-pass
# Two presets with the same folder name in different places, one of them broken (its golden no
# longer matches), and a preset without [[test]]. The copies keep the source's first two cases
# (`default`, `each-pixel-once`), so the counts below do not move when the preset gains cases.
keep_two_cases() { awk '/^\[\[test\]\]/ { ++n } n <= 2' "$1" > "$1.tmp" && mv "$1.tmp" "$1"; }
mkdir -p "$work/a" "$work/b"
cp -r "$src" "$work/a/fsp"; cp -r "$src" "$work/b/fsp"
keep_two_cases "$work/a/fsp/preset.toml"; keep_two_cases "$work/b/fsp/preset.toml"
sed -i 's/vec4(/vec4(0.1 + /' "$work/b/fsp/display.frag"
mkdir "$work/none"; sed '/^\[\[test\]\]/,$d' "$src/preset.toml" > "$work/none/preset.toml"
cp "$src"/*.frag "$src"/*.vert "$work/none/"
cd "$work"

# 1. No [[test]], or a filter that selects nothing: say so, exit 1.
expect_rc 1 none.log "$passlab" test none
grep -q "no \[\[test\]\] cases in 1 preset(s): nothing tested" none.log || fail "no message for a preset without tests"
expect_rc 1 glob.log "$passlab" test a/fsp --case 'zz*'
grep -q "selects none of the 2 case(s)" glob.log || fail "no message for a glob that selects nothing"

# 2. --case selects the cases of every run; a misspelt name is a usage error with a suggestion.
expect_rc 2 typo.log "$passlab" test a/fsp --case defualt
grep -q "did you mean 'default'?" typo.log || fail "no suggestion for --case defualt: $(cat typo.log)"
expect_rc 0 one.log "$passlab" test a/fsp --case each-pixel-once
grep -q "^PASS a/fsp: each-pixel-once" one.log || fail "--case did not run the case"
! grep -q ": default" one.log || fail "--case ran another case too"

# 3. Outputs that cannot be written are environment errors before anything runs.
: > afile
expect_rc 3 w1.log "$passlab" test a/fsp --report /proc/passlab-x
expect_rc 3 w2.log "$passlab" test a/fsp --fail-dir afile
expect_rc 3 w3.log "$passlab" test a/fsp --junit /proc/passlab-x.xml
expect_rc 3 w4.log "$passlab" grade shading/lambert --exercise a/fsp --out afile
expect_rc 3 w5.log "$passlab" gallery -o afile
expect_rc 3 w6.log "$passlab" bench a/fsp --frames 1 --json /proc/passlab-x.json
grep -q "fail-dir afile: exists and is not a folder" w2.log || fail "the --fail-dir message: $(cat w2.log)"

# 4. A failed golden: the summary names the case; actual, expected and diff land under a path
#    unique per preset folder; --junit and --json carry every case, the figures, the images.
expect_rc 1 fails.log "$passlab" test a/fsp b/fsp --fail-dir fd --report report --junit r.xml --json r.json -j 1
grep -A1 "The following cases FAILED:" fails.log | grep -q "    b/fsp: default" || fail "the summary does not list the failed case: $(cat fails.log)"
for f in actual expected diff; do [ -f "fd/b/fsp/default.$f.png" ] || fail "no fd/b/fsp/default.$f.png: $(find fd)"; done
[ -f report/a/fsp/default.png ] && [ -f report/b/fsp/default.png ] || fail "report images collide: $(find report -name '*.png')"
! cmp -s report/a/fsp/default.png report/b/fsp/default.png || fail "the two presets' report images are the same file"
[ "$(grep -c '<testcase ' r.xml)" = 4 ] || fail "junit: expected 4 testcases: $(cat r.xml)"
grep -q '<failure message="golden snapshots/default.png: rmse' r.xml || fail "junit: no failing figures in the message"
grep -q "\[\[ATTACHMENT|$work/fd/b/fsp/default.diff.png\]\]" r.xml || fail "junit: the diff is not attached"
grep -q '"failed": 1' r.json && grep -q '"status": "failed"' r.json || fail "json: no failed case"

# 5. -j 2 and shards: the same cases with the same results.
expect_rc 1 j2.log "$passlab" test a/fsp b/fsp -j 2 --json j2.json
[ "$(grep -c '"status"' j2.json)" = 4 ] && grep -q '"failed": 1' j2.json || fail "-j 2 differs: $(cat j2.log)"
grep -q "    b/fsp: default" j2.log || fail "-j 2: the failed case is not listed"
: > shards.txt
for i in 0 1 2; do
  rc=0; TEST_TOTAL_SHARDS=3 TEST_SHARD_INDEX=$i TEST_SHARD_STATUS_FILE=status "$passlab" test a/fsp b/fsp -j 1 > "s$i.log" 2>&1 || rc=$?
  grep -E "^(PASS|FAIL) " "s$i.log" >> shards.txt
done
[ -f status ] || fail "TEST_SHARD_STATUS_FILE was not touched"
[ "$(sort shards.txt | sed 's/ (.*//' | uniq | wc -l)" = 4 ] && [ "$(wc -l < shards.txt)" = 4 ] || fail "shards do not partition the cases: $(cat shards.txt)"
expect_rc 0 shard.log "$passlab" test a/fsp b/fsp --shard 2/2 -j 1
grep -q "^shard 2/2: 2 of 4 case(s)" shard.log || fail "--shard 2/2: $(cat shard.log)"

# 6. Golden writes are printed and counted without -v; --update --case rewrites only that case.
rm a/fsp/snapshots/default.png
expect_rc 0 wrote.log "$passlab" test a/fsp
grep -q "WROTE golden snapshots/default.png: golden written" wrote.log || fail "the written golden is not printed"
grep -q "^goldens: 1 written, 0 rewritten" wrote.log || fail "no golden count: $(cat wrote.log)"
expect_rc 0 upd.log "$passlab" test a/fsp --update --case default
grep -q "^goldens: 0 written, 1 rewritten" upd.log || fail "--update --case: $(cat upd.log)"
[ "$(grep -c '^PASS' upd.log)" = 1 ] || fail "--update --case ran more than the case"

# 7. check --json: passes, images, params with their widgets.
"$passlab" check procedural/fbm --json - > check.json 2> check.err || fail "check --json: $(cat check.err)"
grep -q '"widget": "slider_int"' check.json && grep -q '"name": "field"' check.json && grep -q '"kind": "fullscreen"' check.json ||
  fail "check --json lacks params, images or passes: $(head -40 check.json)"
echo "passlab test: 7 groups passed"
