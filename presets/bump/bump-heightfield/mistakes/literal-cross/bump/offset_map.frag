#version 450
// Offset map from a height field (000_c9f7e5de708ecbb3.txt L2479-2484: "encode orthogonal
// offsets (dh/du, dh/dv) ... calculate using finite differencing on height field"):
//     h_u ~ (h[x+1] - h[x-1]) / (2 / width),   h_v likewise,   in height units per uv unit
// Writes (h, h_u, h_v, 0) to a float target of the height map's size. The height is read from
// the alpha of `heights` (the layout of bump/heightfield.frag). OFFSET_WRAP 1 (default): the
// field tiles (wrap around); 0: one-sided differences at the border (a ramp stays exact).
layout(location = 0) out vec4 offsets;
uniform sampler2D heights;
#ifndef OFFSET_WRAP
#define OFFSET_WRAP 1
#endif
float h_at(ivec2 p, ivec2 size) {
#if OFFSET_WRAP
    p = (p + size) % size;
#endif
    return texelFetch(heights, p, 0).a;
}
void main() {
    ivec2 size = textureSize(heights, 0), p = ivec2(gl_FragCoord.xy);
    ivec2 lo = p - 1, hi = p + 1;
#if !OFFSET_WRAP
    lo = max(lo, ivec2(0)), hi = min(hi, size - 1);
#endif
    vec2 span = vec2(hi - lo) / vec2(size);  // uv distance between the two samples
    float h_u = (h_at(ivec2(hi.x, p.y), size) - h_at(ivec2(lo.x, p.y), size)) / span.x;
    float h_v = (h_at(ivec2(p.x, hi.y), size) - h_at(ivec2(p.x, lo.y), size)) / span.y;
    offsets = vec4(h_at(p, size), h_u, h_v, 0.0);
}
