#version 450
// EXERCISE — bilinear magnification (000_c9f7e5de708ecbb3.txt L1952-1965), written out in the
// shader (sw) next to the sampler's LINEAR filter (hw), which must agree. Fill in the two TODO
// blocks of bilinear(); as shipped it returns the nearest texel.
//     passlab run   texturing/bilinear-magnification --exercise presets/texturing/bilinear-magnification/exercise
//     passlab grade texturing/bilinear-magnification --exercise presets/texturing/bilinear-magnification/exercise
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hw;
layout(location = 1) out vec4 sw;
uniform sampler2D pattern;
uniform sampler2D pattern_lin;
uniform sampler2D ramp;
uniform sampler2D ramp_lin;

vec4 fetch(ivec2 p) {
    bool r = params.source == SOURCE_RAMP2X2;
    ivec2 size = r ? textureSize(ramp, 0) : textureSize(pattern, 0);
    p = clamp(p, ivec2(0), size - 1);  // clamp-to-edge, like the sampler
    return r ? texelFetch(ramp, p, 0) : texelFetch(pattern, p, 0);
}

vec4 bilinear(vec2 t) {
    vec2 size = vec2(params.source == SOURCE_RAMP2X2 ? textureSize(ramp, 0) : textureSize(pattern, 0));
    // TODO 1: find the texel (u, v) whose centre is at or before the sample point and the
    // fraction (du, dv) past it. t is in [0, 1] over the whole texture; texel i covers
    // [i, i + 1) in texel units and its centre is at i + 0.5 (where the sampler returns that
    // texel unblended). Go to texel units, shift so that centres land on integers, then split
    // into integer part i and fraction d.
    ivec2 i = ivec2(t * size);
    vec2 d = vec2(0.0);
    // TODO 2: the weighted sum of the four texels around the point (000_c9f7e5de708ecbb3.txt
    // L1959-1965), T(u, v) = fetch(i), T(u + 1, v) = fetch(i + ivec2(1, 0)), ...:
    //     T(u+du, v+dv) = du dv T(u+1, v+1) + du (1-dv) T(u+1, v)
    //                   + (1-du) dv T(u, v+1) + (1-du)(1-dv) T(u, v)
    // (fetch clamps to the edge as the sampler's clamp address mode does.)
    return fetch(i);
}

void main() {
    // With the split view each third of the window shows the whole texture.
    vec2 t = params.split ? vec2(fract(uv.x * 3.0), uv.y) : uv;
    hw = params.source == SOURCE_RAMP2X2 ? texture(ramp_lin, t) : texture(pattern_lin, t);
    sw = bilinear(t);
}
