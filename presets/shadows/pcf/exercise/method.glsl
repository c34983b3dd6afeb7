// Exercise: pcf. `passlab grade shadows/pcf --exercise presets/shadows/pcf/exercise`.
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;   // the light's depth map (passes light_*)

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(cameras.light.view_proj, p + b * l);
    // TODO (000_c9f7e5de708ecbb3.txt L4670-4677, 003_cfc3b5b225ddab3d.txt L300-303, L321):
    // percentage-closer filtering with k = params.kernel. Take the k x k texels whose centres are
    // nearest coord.xy (first = floor(coord.xy * size - (k - 1) / 2)), compare coord.z with each
    // stored depth (shadow_compare_texel: 1 lit, 0 shadowed) and return the mean of the k^2
    // compare results:  V = (1 / k^2) * sum_ij [z <= d(first + (i, j))].
    // Filter the results, not the depths.
    return shadow_nearest(shadow, coord);
}
