#version 450
// Bilinear magnification (000_c9f7e5de708ecbb3.txt L1938-1983):
//   T(u + du, v + dv) = du dv T11 + du (1 - dv) T10 + (1 - du) dv T01 + (1 - du)(1 - dv) T00
// with (u, v) the texel whose centre is at or before the sample point and (du, dv) the fraction
// past it (texel centres sit at i + 0.5). hw: the sampler does the same in hardware.
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
    vec2 st = t * size - 0.5;  // texel space, centres on integers
    ivec2 i = ivec2(floor(st));
    vec2 d = st - floor(st);
    return d.x * d.y * fetch(i + ivec2(1, 1)) + d.x * (1.0 - d.y) * fetch(i + ivec2(1, 0)) +
           (1.0 - d.x) * d.y * fetch(i + ivec2(0, 1)) + (1.0 - d.x) * (1.0 - d.y) * fetch(i);
}

void main() {
    // With the split view each third of the window shows the whole texture.
    vec2 t = params.split ? vec2(fract(uv.x * 3.0), uv.y) : uv;
    hw = params.source == SOURCE_RAMP2X2 ? texture(ramp_lin, t) : texture(pattern_lin, t);
    sw = bilinear(t);
}
