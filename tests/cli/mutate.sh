#!/bin/sh
# `passlab mutate`: a deliberately weak test reports its survivor at file:line with the changed
# line; a strong one kills every mutant and exits 0; the choice of mutants is deterministic by
# seed; --json is written; the presets' files are never touched.
# Usage: mutate.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }
tree_hash() { find tests/mutate -type f | sort | xargs sha256sum | sha256sum; }
before=$(tree_hash)
had_failures=no; [ -e test-failures ] && had_failures=yes

rc=0; "$passlab" mutate tests/mutate/weak --max 0 > "$work/weak.txt" 2>&1 || rc=$?
cat "$work/weak.txt"
[ "$rc" = 1 ] || fail "weak: exit $rc, expected 1 (a survivor)"
grep -q 'SURVIVED .*weak.frag:5:23  nudge constant' "$work/weak.txt" || fail "weak: the nudged 0.25 is not reported as a survivor at weak.frag:5:23"
grep -qF '+     color = vec4(vec3(0.275 + 0.5' "$work/weak.txt" || fail "weak: the changed line is not shown"
grep -q 'killed/invariant .*by in-range' "$work/weak.txt" || fail "weak: no kill by the range check"

rc=0; "$passlab" mutate tests/mutate/strong --max 0 --json "$work/strong.json" > "$work/strong.txt" 2>&1 || rc=$?
cat "$work/strong.txt"
[ "$rc" = 0 ] || fail "strong: exit $rc, expected 0 (every mutant killed)"
grep -q 'survived 0' "$work/strong.txt" || fail "strong: survivors reported"
python3 -c "
import json,sys
d=json.load(open('$work/strong.json'))
assert len(d)==6 and all(m['outcome']=='killed/invariant' and m['killed_by']==['exact-values'] for m in d), d
" || fail "strong: --json does not list the 6 mutants killed by exact-values"

# Deterministic: the same seed picks the same mutants, another seed others.
"$passlab" mutate tests/mutate/weak --max 3 --seed 7 2>&1 | grep -E '^  [A-Za-z/-]+ +weak' | awk '{print $2, $3, $4}' > "$work/a.txt" || true
"$passlab" mutate tests/mutate/weak --max 3 --seed 7 2>&1 | grep -E '^  [A-Za-z/-]+ +weak' | awk '{print $2, $3, $4}' > "$work/b.txt" || true
[ "$(wc -l < "$work/a.txt")" = 3 ] || fail "--max 3 did not run 3 mutants"
cmp -s "$work/a.txt" "$work/b.txt" || fail "the same seed chose different mutants"

[ "$(tree_hash)" = "$before" ] || fail "passlab mutate changed files under tests/mutate"
[ "$had_failures" = yes ] || [ ! -e test-failures ] || fail "passlab mutate wrote ./test-failures (failure images belong in its scratch folder)"
echo "mutate: weak survivor reported, strong all killed, deterministic, files untouched"
