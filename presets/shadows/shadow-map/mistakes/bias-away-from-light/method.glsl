// shadow-map: the hard shadow of one nearest depth compare, with constant + slope-scale bias.
// Seeds: 000_c9f7e5de708ecbb3.txt L4575-4585 (the two steps and the compare), L4685-4700 (acne,
// Peter Panning, slope-scale bias); 003_cfc3b5b225ddab3d.txt L252-260 (Williams 78).
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;   // the light's depth map (passes light_*)

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    // (mistake: moves the point AWAY from the light) by b = texel (c + s tan(theta)) before comparing.
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(cameras.light.view_proj, p - b * l);
    return shadow_nearest(shadow, coord);
}
