#version 450
// Exact points of the integral for the tests (one integration per texel: lavapipe stops any
// single shader invocation's loops after 65535 iterations in total, so no texel does more):
//   texel 0: LUT(roughness 0.5, n.v 0.5);  texels 1..11: the bias g at n.v = 1 for roughness
//   0, 0.1, ..., 1;  texel 12: the minimum of r + g over the LUT texels with roughness <= 0.2
//   and n.v >= 0.5 (read from the table).
#include "envmap/brdf_lut.glsl"
layout(location = 0) out vec4 points;
uniform sampler2D lut;
void main() {
    int k = int(gl_FragCoord.x);
    if (k == 0) {
        points = vec4(integrate_brdf(0.5, 0.5, params.samples), 0.0, 1.0);
    } else if (k <= 11) {
        points = vec4(integrate_brdf(0.1 * float(k - 1), 1.0, params.samples).y, 0.0, 0.0, 1.0);
    } else {
        ivec2 size = textureSize(lut, 0);
        float lo = 1e9;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                vec2 at = (vec2(x, y) + 0.5) / vec2(size);
                if (at.x <= 0.2 && at.y >= 0.5) lo = min(lo, texelFetch(lut, ivec2(x, y), 0).b);
            }
        points = vec4(lo, 0.0, 0.0, 1.0);
    }
}
