// Direct light of the Cornell spot with shadow-map visibility: the spot's depth from the light
// camera (`light` of gi/cornell.glsl's TOML), compared by the sampler (one bilinear 2x2 PCF tap:
// the cheapest soft edge on llvmpipe) after a normal offset that grows at grazing angles.
// The graph binds the depth map as `spot_depth`:
//   spot_depth = { format = "d32", size = 1024, sampler = { compare = "less_equal", address = "clamp" } }
#ifndef PASSLAB_GI_RSM_DIRECT_GLSL
#define PASSLAB_GI_RSM_DIRECT_GLSL
#include "gi/cornell.glsl"
uniform sampler2DShadow spot_depth;

float rsm_spot_visibility(vec3 p, vec3 n) {
    vec3 l = normalize(CORNELL_LIGHT_POS - p);
    // Offset along the normal, a few texels' worth at the receiver's distance: no acne on walls at
    // grazing angles, no visible Peter Panning at the blocks' contact lines.
    float texel = distance(CORNELL_LIGHT_POS, p) * 2.0 / abs(cameras.light.proj[1][1]) / float(textureSize(spot_depth, 0).y);
    vec3 q = p + n * texel * (1.5 + 2.0 * (1.0 - max(dot(n, l), 0.0)));
    vec4 c = cameras.light.view_proj * vec4(q, 1.0);
    vec3 s = c.xyz / c.w;
    vec2 uv = s.xy * 0.5 + 0.5;
    if (c.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 0.0;
    return texture(spot_depth, vec3(uv, s.z));
}

// L0 = rho/pi * I(w) cos / d^2 * V (the spot itself is not visible to the camera).
vec3 rsm_direct(vec3 p, vec3 n, vec3 albedo) {
    return albedo / 3.14159265 * cornell_light_irradiance(p, n) * rsm_spot_visibility(p, n);
}
#endif
