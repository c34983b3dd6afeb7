// gaussian-pcf: percentage-closer filtering with Gaussian weights that slide with the point.
// Seeds: 002_644d46bdce7e5305.txt L22 ("optimized gaussian filtered PCF"), L1898-1900 ("use
// Gaussian-filtered PCF at shadow map sampling", after the-witness.net's shadow mapping summary)
// — named, no formula; the filter is passes/shadows/shadow_map.glsl shadow_pcf_gaussian.
// PCF itself: 000_c9f7e5de708ecbb3.txt L4670-4677 (filter the compare results).
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;   // the light's depth map (passes light_*)

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(cameras.light.view_proj, p + b * l);
    return shadow_pcf_gaussian(shadow, coord, params.kernel, params.sigma);
}
