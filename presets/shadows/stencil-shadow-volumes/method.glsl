// The visibility shadows/shade.frag multiplies the direct light by. Shadow volumes decide it with
// the stencil buffer, not in the shader, so the shading pass runs twice with a constant:
//   SV_METHOD 0  "scene" passes: everything unlit (ambient only), depth written;
//   SV_METHOD 1  "lit" passes: the same surfaces again, where stencil == 0 (000 L4835 "all lit
//                surfaces have stencil value of 0"), depth test `equal`: fully lit;
//   SV_METHOD 2  test-only reference: the shared shadow-map lookup (shadows/shadow_map.glsl),
//                nearest compare with constant + slope-scale bias, in the same graph.
#if SV_METHOD == 2
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;
float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    return shadow_nearest(shadow, shadow_project(cameras.light.view_proj, p + b * l));
}
#else
float shadow_visibility(vec3 p, vec3 n, vec3 l) { return float(SV_METHOD); }
#endif
