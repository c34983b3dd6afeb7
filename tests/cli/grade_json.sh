#!/bin/sh
# What a course platform reads from `passlab grade`: --json in passlab's schema and Gradescope's
# results.json, scored by case weights, hidden cases without their figures, a submission that
# does not build scored 0 on every case; `passlab new --exercise` gives a student a working copy;
# `check` refuses a bad weight or visibility at its key. Parsed with python3 (json module).
# Usage: grade_json.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
preset=presets/shading/lambert
n=$(grep -c '^\[\[test\]\]' "$preset/preset.toml")  # the preset's cases, each worth 1 by default
py() { python3 -c "import json,sys; n=int(sys.argv[2]); j=json.load(open(sys.argv[1])); $2" "$1" "$n" || fail "$3: $(cat "$1")"; }

# 1. The student's working copy: only the exercise files, never inside the preset, never over a folder.
"$passlab" new "$work/mine" --exercise shading/lambert > "$work/new.txt" || fail "new --exercise failed"
[ -f "$work/mine/lambert.frag" ] && [ -f "$work/mine/README.md" ] || fail "new --exercise did not copy the exercise"
[ ! -e "$work/mine/preset.toml" ] || fail "new --exercise copied the whole preset"
cmp -s "$work/mine/lambert.frag" "$preset/exercise/lambert.frag" || fail "the copy differs from exercise/"
grep -q "passlab grade shading/lambert --exercise $work/mine" "$work/new.txt" || fail "no grade command printed"
rc=0; "$passlab" new "$work/mine" --exercise shading/lambert > /dev/null 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "new --exercise over an existing folder: exit $rc, expected 2"
rc=0; "$passlab" new "$work/none" --exercise aa/fxaa-smaa > /dev/null 2> "$work/none.err" || rc=$?
[ "$rc" = 2 ] && grep -q "has no exercise/ folder" "$work/none.err" || fail "a preset without exercise/: exit $rc"

# 2. The unsolved copy, passlab's schema: every case failed with its hint and figures, score 0 of n.
rc=0; "$passlab" grade shading/lambert --exercise "$work/mine" --out "$work/o1" --json "$work/g1.json" > "$work/g1.txt" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "unsolved: exit $rc"
grep -q "grade: 0 of $n cases pass with .* (score 0 of $n)" "$work/g1.txt" || fail "unsolved summary: $(cat "$work/g1.txt")"
py "$work/g1.json" "assert j['graded'] and j['score'] == 0 and j['max_score'] == n and j['failed'] == n, j
c = {x['name']: x for x in j['cases']}
assert all(x['status'] == 'failed' and x['hint'] and x['checks'] for x in c.values()), c
assert any('difference' in k for k in c['default']['checks']), c['default']" "passlab JSON of the unsolved copy"

# 3. The reference solution in Gradescope's schema: full marks, every test passed.
mkdir "$work/solved"; cp "$preset/lambert.frag" "$work/solved/"
"$passlab" grade shading/lambert --exercise "$work/solved" --out "$work/o2" --json "$work/g2.json" --format gradescope > "$work/g2.txt" 2>&1 || fail "solved: $(cat "$work/g2.txt")"
py "$work/g2.json" "assert j['score'] == n and isinstance(j['execution_time'], int) and 'score %d of %d' % (n, n) in j['output'], j
assert len(j['tests']) == n and all(t['status'] == 'passed' and t['score'] == t['max_score'] == 1 and t['visibility'] == 'visible' for t in j['tests']), j" "Gradescope JSON of the solution"

# 4. A mistake that fails one case: its hint is in that test's output, the score is n minus the failed cases.
rc=0; "$passlab" grade shading/lambert --exercise "$preset/mistakes/unnormalised-light" --out "$work/o3" --json "$work/g3.json" --format gradescope > /dev/null 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "a mistake: exit $rc"
py "$work/g3.json" "f = [t for t in j['tests'] if t['status'] == 'failed']
assert len(f) >= 1 and j['score'] == n - len(f) and all('hint:' in t['output'] for t in f), j" "Gradescope JSON of a mistake"

# 5. A submission that does not build: 0 on every declared case, the compile error as output.
mkdir "$work/broken"; sed 's/vec3 lo = vec3(0.0);/vec3 lo = vec3(0.0)/' "$preset/exercise/lambert.frag" > "$work/broken/lambert.frag"
rc=0; "$passlab" grade shading/lambert --exercise "$work/broken" --json "$work/g4.json" --format gradescope > /dev/null 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "broken: exit $rc"
py "$work/g4.json" "assert j['score'] == 0 and len(j['tests']) == n and all(t['status'] == 'failed' and 'lambert.frag:' in t['output'] for t in j['tests']), j" "Gradescope JSON of a broken copy"

# 6. Weights and visibility: a copy of the preset with `default` worth 2 and `white-furnace` hidden.
"$passlab" new "$work/weighted" --from shading/lambert > /dev/null || fail "new --from"
python3 - "$work/weighted/preset.toml" <<'PY'
import sys
p = sys.argv[1]; s = open(p).read()
s = s.replace('name   = "default"\n', 'name   = "default"\nweight = 2\n', 1)
s = s.replace('name = "white-furnace"\n', 'name = "white-furnace"\nvisibility = "hidden"\n', 1)
open(p, 'w').write(s)
PY
rc=0; "$passlab" grade "$work/weighted" --exercise "$work/mine" --out "$work/o5" --json "$work/g5.json" > "$work/g5.txt" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "weighted: exit $rc"
grep -q "^FAIL default (2 points)" "$work/g5.txt" || fail "no points shown: $(cat "$work/g5.txt")"
grep -q "^FAIL white-furnace (hidden case: figures not shown)" "$work/g5.txt" || fail "hidden case shown: $(cat "$work/g5.txt")"
! grep -q "L_o must be 1 everywhere" "$work/g5.txt" || fail "the hidden case's hint was printed"
py "$work/g5.json" "c = {x['name']: x for x in j['cases']}
assert j['max_score'] == n + 1 and c['default']['max_score'] == 2, j
h = c['white-furnace']; assert h['visibility'] == 'hidden' and 'checks' not in h and 'hint' not in h, h" "weights and visibility"
"$passlab" grade "$work/weighted" --exercise "$work/solved" --out "$work/o6" --json "$work/g6.json" --format gradescope > /dev/null 2>&1 || fail "weighted solved"
py "$work/g6.json" "t = {x['name']: x for x in j['tests']}
assert j['score'] == n + 1 and t['white-furnace']['visibility'] == 'hidden' and t['white-furnace']['output'], j" "Gradescope weights"

# 7. Bad values are refused at their key; --format without --json is a usage error.
sed -i 's/^visibility = "hidden"/visibility = "hiden"/' "$work/weighted/preset.toml"
rc=0; "$passlab" check "$work/weighted" > /dev/null 2> "$work/c1.err" || rc=$?
[ "$rc" = 1 ] && grep -q "preset.toml:[0-9]*:[0-9]*: .*hiden" "$work/c1.err" && grep -q "hidden" "$work/c1.err" || fail "a misspelt visibility: exit $rc: $(cat "$work/c1.err")"
sed -i 's/^visibility = "hiden"/visibility = "hidden"/; s/^weight = 2$/weight = -1/' "$work/weighted/preset.toml"
rc=0; "$passlab" check "$work/weighted" > /dev/null 2> "$work/c2.err" || rc=$?
[ "$rc" = 1 ] && grep -q "preset.toml:[0-9]*:[0-9]*: .*weight must be" "$work/c2.err" || fail "a negative weight: exit $rc: $(cat "$work/c2.err")"
rc=0; "$passlab" grade shading/lambert --exercise "$work/solved" --format gradescope > /dev/null 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "--format without --json: exit $rc, expected 2"
echo "passlab grade --json: 7 cases passed"
