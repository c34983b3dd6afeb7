#!/bin/sh
# `--set NAME=FILE` on an image: an ISF image input and a Shadertoy texture channel (whose
# procedural stand-ins are images `NAME` and `<pass>_ch<N>`) take the user's picture, with no
# preset edited; the picture decides what renders (checked byte for byte against the picture
# itself, both written by passlab's encoder). A rendered image, a param typo and a missing
# file are errors naming them.
# Usage: set_image.sh PASSLAB WORKDIR
set -eu
passlab=$1 work=$2
rm -rf "$work"; mkdir -p "$work/toy"
fail() { echo "FAIL: $1" >&2; exit 1; }

# The picture: an 8x8 flat colour rendered by passlab itself.
cat > "$work/red.fs" <<'FS'
/*{ "ISFVSN": "2", "INPUTS": [] }*/
void main() { gl_FragColor = vec4(0.8, 0.2, 0.1, 1.0); }
FS
"$passlab" render "$work/red.fs" -o "$work/pic" --size 8x8 > /dev/null 2>&1 || fail "could not render the picture"
pic="$work/pic/red.png"

# ISF: an image input shown as it is.
cat > "$work/show.fs" <<'FS'
/*{ "ISFVSN": "2", "INPUTS": [ { "NAME": "inputImage", "TYPE": "image" } ] }*/
void main() { gl_FragColor = IMG_NORM_PIXEL(inputImage, vec2(0.5)); }
FS
"$passlab" render "$work/show.fs" -o "$work/isf" --size 8x8 --set "inputImage=$pic" > /dev/null 2> "$work/isf.txt" ||
  { cat "$work/isf.txt" >&2; fail "ISF render with --set inputImage=FILE"; }
cmp -s "$work/isf/show.png" "$pic" || fail "ISF: the output is not the picture set as inputImage"
"$passlab" render "$work/show.fs" -o "$work/isf-grid" --size 8x8 > /dev/null 2>&1 || fail "ISF render without --set"
if cmp -s "$work/isf-grid/show.png" "$pic"; then fail "ISF: the uv-grid stand-in renders like the picture (the check could not fail)"; fi

# Shadertoy folder: a texture channel's stand-in replaced.
cat > "$work/toy/image.glsl" <<'GLSL'
void mainImage(out vec4 c, in vec2 p) { c = vec4(texture(iChannel0, vec2(0.5)).rgb, 1.0); }
GLSL
printf '[image]\niChannel0 = { texture = "RGBA Noise Medium", filter = "nearest" }\n' > "$work/toy/channels.toml"
"$passlab" render "$work/toy" -o "$work/st" --size 8x8 --set "image_ch0=$pic" > /dev/null 2> "$work/st.txt" ||
  { cat "$work/st.txt" >&2; fail "Shadertoy render with --set image_ch0=FILE"; }
cmp -s "$work/st/toy.png" "$pic" || fail "Shadertoy: the output is not the picture set as image_ch0"

# Errors: a rendered image, a missing file, a name that is neither a param nor an image.
rc=0; "$passlab" render "$work/show.fs" -o "$work/e1" --size 8x8 --set "image=$pic" > /dev/null 2> "$work/e1.txt" || rc=$?
[ "$rc" != 0 ] && grep -q "rendered by the graph" "$work/e1.txt" || { cat "$work/e1.txt" >&2; fail "a rendered image: exit $rc"; }
rc=0; "$passlab" render "$work/show.fs" -o "$work/e2" --size 8x8 --set "inputImage=$work/nope.png" > /dev/null 2> "$work/e2.txt" || rc=$?
[ "$rc" != 0 ] && grep -q "no such image file" "$work/e2.txt" || { cat "$work/e2.txt" >&2; fail "a missing file: exit $rc"; }
rc=0; "$passlab" render "$work/show.fs" -o "$work/e3" --size 8x8 --set "inputImag=$pic" > /dev/null 2> "$work/e3.txt" || rc=$?
[ "$rc" != 0 ] || { cat "$work/e3.txt" >&2; fail "an unknown name was accepted"; }
for e in e1 e2 e3; do [ ! -e "$work/$e" ] || [ -z "$(ls -A "$work/$e")" ] || fail "$e wrote output although it failed"; done
echo "ok"
