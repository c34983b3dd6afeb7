// pcf: percentage-closer filtering, an n x n block of nearest depth compares averaged.
// Seeds: 000_c9f7e5de708ecbb3.txt L4670-4677 ("normal bilinear filtering cannot be used on
// depth ... must filter lookup result, not depth"); 003_cfc3b5b225ddab3d.txt L300-303 (several
// lookups around the coordinate, the fraction in shadow modulates the light), L321 (16 lookups).
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;   // the light's depth map (passes light_*)

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    // A kernel reaching (n - 1) / 2 texels from the point compares against depths that far
    // away: the slope-scale term must cover them too (bias_slope >= 0.71 + (n - 1) / 2).
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(cameras.light.view_proj, p + b * l);
    return shadow_pcf_grid(shadow, coord, params.kernel);
}
