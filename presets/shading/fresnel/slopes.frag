#version 450
// With SLOPES: R(theta_{x+1}) - R(theta_x) per formula (>= 0 means monotone). Without: the
// values at exactly 0 (x = 0) and 90 degrees (x = 1).
#include "common/fresnel.glsl"
layout(location = 0) out vec4 result;
vec3 all3(float c) {
    float f0 = fresnel_f0(params.n1, params.n2);
    return vec3(fresnel_exact(c, params.n1, params.n2), fresnel_schlick(c, f0), fresnel_schlick_sg(c, f0));
}
void main() {
#ifdef SLOPES
    const float step_ = 1.57079632679 / 512.0;
    float theta = gl_FragCoord.x * step_;
    result = vec4(all3(cos(theta + step_)) - all3(cos(theta)), 1.0);
#else
    // cos(pi/2) in float is -4.4e-8, not 0: the grazing end passes cos = 0 exactly.
    result = vec4(all3(gl_FragCoord.x < 1.0 ? 1.0 : 0.0), 1.0);
#endif
}
