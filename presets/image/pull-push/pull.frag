#version 450
// Pull (000_c9f7e5de708ecbb3.txt L5258-5275, hole filling by a pyramid; the weights of Gortler et
// al. 1996, "The Lumigraph", section 3.3): from its 2x2 children at level k (premultiplied
// (c a, a)), a texel of level k + 1 gets the weighted mean colour
//     c = sum a_i c_i / sum a_i        and the weight  a = min(1, sum a_i)
// so a coarse texel with any sample below it counts as full: the push then fills a hole from the
// finest level that has samples around it, not from a level diluted by the hole itself.
// (Sides are powers of two here, so every texel has exactly four children.)
layout(location = 0) out vec4 color;
uniform sampler2D fine;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
    vec4 s = texelFetch(fine, p, 0) + texelFetch(fine, p + ivec2(1, 0), 0)
           + texelFetch(fine, p + ivec2(0, 1), 0) + texelFetch(fine, p + ivec2(1, 1), 0);
    float a = min(1.0, s.a);
    color = s.a > 0.0 ? vec4(s.rgb / s.a * a, a) : vec4(0.0);
}
