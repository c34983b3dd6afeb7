#version 450
// Test-only: the penumbra's width in the two bakes (light radius r and 2r), along a ground line
// from the box's footprint centre away from the light, t = 0.6 .. 3.0 world units in steps of
// one lightmap texel: the number of texels whose visibility lies strictly inside (0.02, 0.98).
// penumbra = (w_r, w_2r, |w_2r - 2 w_r|, 0), in texels. Geometry says w grows as
// 2 r (d_receiver - d_edge) / d_edge (similar triangles through the shadow's far edge), linearly
// in r, so |w_2r - 2 w_r| stays within a texel or so of 0.
layout(local_size_x = 1) in;
#include "shadows/scene.glsl"
uniform sampler2D lightmap;
uniform sampler2D lightmap2;
layout(std430) writeonly buffer Penumbra { float w[4]; } penumbra;
float width(sampler2D map) {
    float texel = 6.0 / float(textureSize(map, 0).x);
    vec2 away = -normalize(cameras.light.position.xz);
    int n = 0;
    for (float t = 0.6; t <= 3.0; t += texel) {
        vec2 p = SHADOW_BOX_AT.xz + away * t;
        float v = texelFetch(map, ivec2(floor((p / 6.0 + 0.5) * vec2(textureSize(map, 0)))), 0).r;
        n += v > 0.02 && v < 0.98 ? 1 : 0;
    }
    return float(n);
}
void main() {
    float a = width(lightmap), b = width(lightmap2);
    penumbra.w[0] = a;
    penumbra.w[1] = b;
    penumbra.w[2] = abs(b - 2.0 * a);
    penumbra.w[3] = 0.0;
}
