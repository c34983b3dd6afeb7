// Exercise: shadow-map. Fill in the two TODOs; `passlab grade shadows/shadow-map --exercise
// presets/shadows/shadow-map/exercise` checks them (acne at 10, 45, 80 degrees; ray-traced
// agreement outside 2-texel edge bands; the contact line at a grazing light).
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;   // the light's depth map (passes light_*)

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    // TODO 1 (000_c9f7e5de708ecbb3.txt L4685-4700, slope-scale bias): the world distance
    //     b = texel * (params.bias_constant + params.bias_slope * tan(theta)),  cos(theta) = N.L
    // (clamp tan(theta) to SHADOW_MAX_SLOPE), and move the point TOWARDS the light by b.
    float b = 0.0;
    vec3 q = p;
    // TODO 2 (000 L4581-4585): project q into the light's map (cameras.light.view_proj) to
    // (u, v, depth), fetch the texel under (u, v) and return 1 (lit) when depth <= stored,
    // 0 (shadow) when the depth is larger. Outside the map: lit.
    return 1.0;
}
