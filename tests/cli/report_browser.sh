#!/bin/sh
# The HTML report as a browser shows it (headless Chromium, which scripts/deps.sh installs for
# the test suite): failures come first and are linked from the "Failed:" summary, the failed
# filter is on when something failed, a failed check shows the image it read (tone-mapped when
# HDR), #inspect=<case> opens the image inspector at 4x with rendered/golden/diff, and
# --report-failures-only keeps a green run's report to one page without images.
# Usage: report_browser.sh PASSLAB WORKDIR
set -eu
unset CI  # a missing golden is written locally, as a developer sees it
passlab=$(realpath "$1") work=$2
rm -rf "$work"; mkdir -p "$work"
fail() { echo "FAIL: $1" >&2; exit 1; }
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
[ -n "$browser" ] || fail "no Chromium on PATH (scripts/deps.sh --browser installs it)"
src=presets/fundamentals/fullscreen-pass
keep_two_cases() { awk '/^\[\[test\]\]/ { ++n } n <= 2' "$1" > "$1.tmp" && mv "$1.tmp" "$1"; }
mkdir -p "$work/good" "$work/bad"
cp -r "$src" "$work/good/fsp"; cp -r "$src" "$work/bad/fsp"
keep_two_cases "$work/good/fsp/preset.toml"; keep_two_cases "$work/bad/fsp/preset.toml"
# The bad copy: its golden no longer matches, and a check on an HDR image it renders fails.
sed -i 's/vec4(/vec4(0.1 + /' "$work/bad/fsp/display.frag"
cat >> "$work/bad/fsp/preset.toml" <<'TOML'

[[test]]
name = "hdr-check-fails"
checks = [ { kind = "range", pass = "hot", min = 0.0, max = 1.0 } ]
TOML
sed -i 's/^\[images\]$/[images]\nhot = { format = "rgba16f" }/' "$work/bad/fsp/preset.toml"
grep -q '^hot = ' "$work/bad/fsp/preset.toml" || printf '\n[images]\nhot = { format = "rgba16f" }\n' >> "$work/bad/fsp/preset.toml"
cat >> "$work/bad/fsp/preset.toml" <<'TOML'

[[pass]]
name = "hot"
fragment = "hot.frag"
targets = ["hot"]
TOML
cat > "$work/bad/fsp/hot.frag" <<'GLSL'
#version 450
layout(location = 0) out vec4 o;
void main() { o = vec4(gl_FragCoord.x * 0.05, 0.5, 4.0, 1.0); }  // HDR: up to 12.8 in red
GLSL
cd "$work"
"$passlab" check bad/fsp > check.log 2>&1 || fail "the bad copy does not pass check: $(cat check.log)"
rc=0; "$passlab" test good/fsp bad/fsp --report rep -j 1 > run.log 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "test exited $rc, expected 1: $(cat run.log)"
[ -f rep/index.html ] || fail "no rep/index.html"
# The page as Chromium's DOM has it after the script ran.
shoot() {  # shoot URL PNG DOM [WxH]  (a profile of its own: HOME may be read-only in CI)
  "$browser" --headless --no-sandbox --disable-gpu --disable-background-networking --disable-extensions \
    --user-data-dir="$(pwd)/chrome" --hide-scrollbars --window-size="${4:-1280,900}" --screenshot="$2" "$1" > /dev/null 2>&1 || true
  "$browser" --headless --no-sandbox --disable-gpu --disable-background-networking --disable-extensions \
    --user-data-dir="$(pwd)/chrome" --virtual-time-budget=2000 --dump-dom "$1" > "$3" 2> /dev/null || fail "chromium could not load $1"
}
url="file://$(pwd)/rep/index.html"
shoot "$url" report.png dom.html
[ -s report.png ] || fail "no screenshot"
python3 - dom.html <<'PY' || fail "the report's DOM is not what the browser should show (above)"
import re, sys
dom = open(sys.argv[1]).read()
rows = re.findall(r'<tr class="case"([^>]*)>', dom)
status = [re.search(r'data-status="(\w+)"', r).group(1) for r in rows]
hidden = ['hidden' in r for r in rows]
print("rows", list(zip(status, hidden)))
assert status and status[0] == "fail", "failures are not first"
first_pass = status.index("pass")
assert all(s == "fail" for s in status[:first_pass]) and "fail" not in status[first_pass:], "a failure after a pass"
assert all(h == (s == "pass") for s, h in zip(status, hidden)), "the failed filter is not on: passes shown or failures hidden"
shown = re.search(r'<span id="shown">([^<]*)</span>', dom).group(1)
assert shown == "%d of %d cases shown" % (status.count("fail"), len(rows)), shown
ids = set(re.findall(r'<tr class="case" id="([^"]+)"', dom))
links = re.findall(r'<div id="failed">.*?</div>', dom, re.S)[0]
targets = re.findall(r'href="#([^"]+)"', links)
assert len(targets) == status.count("fail") and all(t in ids for t in targets), ("summary links", targets)
assert 'data-label="check read (tone-mapped)"' in dom, "the failed HDR check does not show the image it read"
PY
# The tone-mapped image the check read: red grows along x, green mid, blue (4.0) well below white.
png=$(ls rep/bad/fsp/hdr-check-fails.check-*.tonemapped.png 2>/dev/null | head -1)
[ -n "$png" ] || fail "no tone-mapped check image: $(find rep -name '*check*')"
# The inspector opened by the link: 4x, the case's images as buttons.
id=$(python3 -c "import re;print(re.findall(r'href=\"#([^\"]+default)\"', open('rep/index.html').read())[0])")
shoot "$url#inspect=$id" inspector.png dom2.html
python3 - dom2.html <<'PY' || fail "the inspector did not open as the link asks"
import re, sys
dom = open(sys.argv[1]).read()
zoom = re.search(r'<div id="zoom"[^>]*>', dom).group(0)
assert 'hidden' not in zoom, zoom
title = re.search(r'<b id="ztitle">([^<]*)</b>', dom).group(1)
assert "default" in title and "(4x)" in title, title
labels = re.findall(r'<button data-i="\d+"[^>]*>([^<]+)</button>', re.search(r'<span id="zviews">.*?</span>', dom, re.S).group(0))
assert labels[:3] == ["rendered", "golden", "diff"], labels
width = re.search(r'<img id="zimg"[^>]*style="width: (\d+)px', dom)
assert width and int(width.group(1)) % 4 == 0, "the image is not drawn at 4x its size"
PY
# Failures only: a green run's report is the page alone; a red run keeps only failures' images.
"$passlab" test good/fsp --report green-all > /dev/null 2>&1 || fail "the good copy fails"
"$passlab" test good/fsp --report green --report-failures-only > /dev/null 2>&1 || fail "the good copy fails with --report-failures-only"
[ -z "$(find green -name '*.png')" ] || fail "a green failures-only report keeps images: $(find green -name '*.png')"
grep -q "failures only" green/index.html || fail "the failures-only report does not say so"
! grep -q '<tr class="case"' green/index.html || fail "a green failures-only report lists cases"
rc=0; "$passlab" test good/fsp bad/fsp --report red --report-failures-only -j 1 > /dev/null 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "the red run exited $rc"
[ -z "$(find red/good -name '*.png' 2>/dev/null)" ] || fail "a failures-only report keeps a passing case's render"
[ -n "$(find red/bad -name '*.png')" ] || fail "a failures-only report lost the failures' images"
rc=0; "$passlab" test good/fsp --report-failures-only > usage.log 2>&1 || rc=$?
[ "$rc" = 2 ] || fail "--report-failures-only without --report exited $rc: $(cat usage.log)"
echo "report: failures first and linked, filter, tone-mapped check image, inspector; green report $(du -sk green-all | cut -f1) KiB -> $(du -sk green | cut -f1) KiB with --report-failures-only"
