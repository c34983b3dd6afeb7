#version 450
// Test reference for simplex_noise (passes/common/noise.glsl, 004_9a40ad89bdfc582a.txt
// L421-425): the same sum written as its definition, over every lattice corner near p rather
// than the 3 of p's triangle, with its own skew constants:
//     n(p) = 70 * sum over corners c of max(0, 0.5 - |p - U(c)|^2)^4 * dot(g(c), p - U(c))
// U(c) = c - (c.x + c.y) G2 maps a skewed integer corner to the plane, g(c) is the corner's
// random unit gradient (the same hash as the lab's). The kernel radius^2 0.5 reaches only the
// triangles incident to a corner (004 L425), so the 4 x 4 skewed cells around p hold every
// corner that contributes and the lab's 3-corner sum must give the same value: a wrong skew or
// unskew constant, the wrong corner for p's triangle or another kernel radius do not.
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float brute;
void main() {
    const float F2 = (sqrt(3.0) - 1.0) / 2.0, G2 = (3.0 - sqrt(3.0)) / 6.0;
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0) * params.frequency;  // as noise.frag, octave 0
    vec2 base = floor(p + (p.x + p.y) * F2);
    float n = 0.0;
    for (int b = -1; b <= 2; ++b)
        for (int a = -1; a <= 2; ++a) {
            vec2 c = base + vec2(a, b);
            vec2 d = p - (c - (c.x + c.y) * G2);
            float t = 0.5 - dot(d, d);
            if (t > 0.0) {
                float ang = 6.2831853 * hash_pcg(vec3(c, 7.0));
                n += t * t * t * t * dot(vec2(cos(ang), sin(ang)), d);
            }
        }
    brute = 70.0 * n;
}
