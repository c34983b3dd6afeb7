// Direct light of the Cornell spot with shadow-map visibility: the spot's depth from the light
// camera (`light` of gi/cornell.glsl's TOML), compared with a 3x3 PCF and a slope-scaled bias.
// The graph binds the depth map as `spot_depth` (d32, clamp, nearest).
#ifndef PASSLAB_GI_RSM_DIRECT_GLSL
#define PASSLAB_GI_RSM_DIRECT_GLSL
#include "gi/cornell.glsl"
uniform sampler2D spot_depth;

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
    vec2 ts = 1.0 / vec2(textureSize(spot_depth, 0));
    float lit = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) lit += s.z <= texture(spot_depth, uv + vec2(x, y) * ts).r ? 1.0 : 0.0;
    return lit / 9.0;
}

// L0 = rho/pi * I(w) cos / d^2 * V (the spot itself is not visible to the camera).
vec3 rsm_direct(vec3 p, vec3 n, vec3 albedo) {
    return albedo / 3.14159265 * cornell_light_irradiance(p, n) * rsm_spot_visibility(p, n);
}
#endif
