#version 450
// R(theta) for theta at texel centres of [0, 90) degrees, by the three formulas.
#include "common/fresnel.glsl"
layout(location = 0) out float exact;
layout(location = 1) out float schlick;
layout(location = 2) out float sg;
void main() {
    float theta = (gl_FragCoord.x / 512.0) * 1.57079632679;
    float c = cos(theta), f0 = fresnel_f0(params.n1, params.n2);
    exact = fresnel_exact(c, params.n1, params.n2);
    schlick = fresnel_schlick(c, f0);
    sg = fresnel_schlick_sg(c, f0);
}
