#version 450
// A colour ramp with holes (the "imperfect" point-sampled surface of 000_c9f7e5de708ecbb3.txt
// L5258-5275): `original` = the ramp, alpha 1 where a sample exists and 0 in a hole (a random
// `holes` share of the texels, and a 12x12 block); `ramp` = the ramp everywhere (what the holes
// hid, for the test); pull level 0 = the samples premultiplied by their alpha (c a, a).
#include "common/hash.glsl"

layout(location = 0) out vec4 out_pull;
layout(location = 1) out vec4 out_original;
layout(location = 2) out vec4 out_ramp;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = frame.target.xy;
    vec3 c = vec3(vec2(p) / (size - 1.0), 0.5);
    bool hole = hash_pcg(vec3(p, float(params.seed))) < params.holes
             || (p.x >= 70 && p.x < 82 && p.y >= 40 && p.y < 52);
    float a = hole ? 0.0 : 1.0;
    out_pull = vec4(c * a, a);
    out_original = vec4(c, a);
    out_ramp = vec4(c, 1.0);
}
