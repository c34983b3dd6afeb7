// The cascade lookup of cascaded-shadow-maps and sdsm: pick the cascade by view distance, a
// nearest compare with the bias in that cascade's own texels, blend into the next cascade over
// its band (000_c9f7e5de708ecbb3.txt L4717: cascades overlap for blending; 002 L1898).
// Needs params bias_constant, bias_slope, cascades; binds `csm` (2D array depth) and `cascades`.
#include "shadows/shadow_map.glsl"
#include "shadows/cascades.glsl"
uniform sampler2DArray csm;
layout(std430) readonly buffer Cascades { ShadowCascade c[SHADOW_MAX_CASCADES]; } cascades_in;

// Cascade bookkeeping of the last lookup, for the debug target `cascade_info`.
int shadow_cascade_used = -1;
float shadow_cascade_blend = 0.0, shadow_cascade_diff = 0.0, shadow_cascade_inside = 1.0;

bool shadow_in_box(vec3 coord) { return all(greaterThanEqual(coord, vec3(0.0))) && all(lessThanEqual(coord, vec3(1.0))); }

float shadow_cascade_visibility(int i, vec3 p, vec3 n, vec3 l) {
    ShadowCascade c = cascades_in.c[i];
    // TODO 1 (000_c9f7e5de708ecbb3.txt L4685-4700 per cascade): the slope-scale bias in THIS
    // cascade's texels: c.range.w is its texel's world size (cascades.comp). A coarser cascade
    // needs a proportionally larger bias.
    float b = shadow_bias_world(0.01, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(c.view_proj, p + b * l);
    if (!shadow_in_box(coord)) shadow_cascade_inside = 0.0;
    ivec2 size = textureSize(csm, 0).xy;
    ivec2 t = clamp(ivec2(floor(coord.xy * vec2(size))), ivec2(0), size - 1);
    return coord.z <= texelFetch(csm, ivec3(t, i), 0).r || coord.z > 1.0 ? 1.0 : 0.0;
}

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float d = -(frame.view * vec4(p, 1.0)).z;   // view distance along the view axis
    int count = params.cascades, i = 0;
    // Beyond the last split there is no cascade: lit (the "shadow distance" of engines).
    if (d > cascades_in.c[count - 1].range.y) return 1.0;
    // TODO 2 (000 L4712-4713): pick the cascade: the first i whose slice ends beyond the point,
    // d <= cascades_in.c[i].range.y (range = (from, to, band width w, texel)).
    shadow_cascade_used = i;
    float v = shadow_cascade_visibility(i, p, n, l);
    // TODO 3 (000 L4717: cascades overlap for blending): in the band at the far end of cascade
    // i, d > to - w (and i + 1 < count), blend into cascade i + 1 with weight
    // f = (d - (to - w)) / w:  v = mix(v_i, v_(i+1), f). Set shadow_cascade_blend = f and
    // shadow_cascade_diff = |v_(i+1) - v_i| for the debug target.
    return v;
}

// Debug target `cascade_info`: (cascade used, 1 if the point lies inside every cascade box it
// was looked up in, blend weight into the next cascade, |v_i - v_{i+1}| in the band).
vec4 shadow_debug() { return vec4(float(shadow_cascade_used), shadow_cascade_inside, shadow_cascade_blend, shadow_cascade_diff); }

// Debug tint (shade.frag's SHADOW_TINT hook), when params.show_cascades: cascade 0 red, 1 green,
// 2 blue, 3 yellow, the blend bands mixing the two by their weight; no cascade: untinted.
vec3 shadow_tint_of(int i) {
    return i == 0 ? vec3(1.0, 0.55, 0.55) : i == 1 ? vec3(0.55, 1.0, 0.55) : i == 2 ? vec3(0.55, 0.65, 1.0) : i == 3 ? vec3(1.0, 1.0, 0.5) : vec3(1.0);
}
vec3 shadow_tint() {
    if (!params.show_cascades || shadow_cascade_used < 0) return vec3(1.0);
    return mix(shadow_tint_of(shadow_cascade_used), shadow_tint_of(shadow_cascade_used + 1), shadow_cascade_blend);
}
