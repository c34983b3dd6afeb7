#version 450
// Push: from the coarsest level down, each level keeps what its samples cover and takes the rest
// from the filled level above, interpolated bilinearly:
//     F_k = P_k.rgb + (1 - P_k.a) * bilinear(F_(k+1))      (P premultiplied, F filled, alpha 1)
// A full texel (a = 1) keeps its own colour exactly; an empty one (a = 0) takes the coarser
// estimate. TOP: the 1x1 top level, F = P.rgb / P.a (the mean of all samples).
layout(location = 0) out vec4 color;
uniform sampler2D fine;     // P_k
#ifndef TOP
uniform sampler2D coarse;   // F_(k+1)
#endif
layout(location = 0) in vec2 uv;

void main() {
    vec4 pk = texelFetch(fine, ivec2(gl_FragCoord.xy), 0);
#ifdef TOP
    color = vec4(pk.a > 0.0 ? pk.rgb / pk.a : vec3(0.0), 1.0);
#else
    vec3 up = texture(coarse, uv).rgb;
    color = vec4(pk.rgb + (1.0 - pk.a) * up, 1.0);
#endif
}
