#version 450
// Fits every cascade (cascades.glsl): thread i takes the view sub-frustum between view distances
// [z_i - w_{i-1}, z_{i+1}] (overlapping the previous cascade by its blend band), projects its 8
// corners with the light camera `light` (an ortho camera: its NDC xy is affine in world
// space), and keeps the light's NDC square that bounds them; the light's full depth range is
// kept, so every caster between the light and the slice is in the map. Defines: CASCADES_ZMIN /
// CASCADES_ZMAX (expressions for the partitioned range), CASCADES_LAMBDA, CASCADES_BLEND,
// CASCADES_N, CASCADES_MAP (map side, texels).
layout(local_size_x = 4) in;
#include "shadows/cascades.glsl"
layout(std430) writeonly buffer Cascades { ShadowCascade c[SHADOW_MAX_CASCADES]; } cascades_out;
#ifdef CASCADES_FROM_DEPTH
// SDSM (002_644d46bdce7e5305.txt L1891-1893): the partitioned range is the depth buffer's tight
// [zmin, zmax], reduced by sdsm_reduce.comp into `zbits` (~bits of the min, bits of the max).
// `splits` records (zmin, zmax, z_0 .. z_N) for the tests.
layout(std430) readonly buffer ZBits { uint w[2]; } zbits;
layout(std430) writeonly buffer Splits { float z[3 + SHADOW_MAX_CASCADES]; } splits;
#endif

vec3 view_corner(float x, float y, float dist) {
    // The view-space point at distance `dist` along -Z through ndc (x, y), to world.
    vec4 clip = frame.proj * vec4(0.0, 0.0, -dist, 1.0);
    vec4 w = frame.inv_view_proj * vec4(x, y, clip.z / clip.w, 1.0);
    return w.xyz / w.w;
}

void main() {
    int i = int(gl_GlobalInvocationID.x), n = CASCADES_N;
    if (i >= n) return;
    float zmin = CASCADES_ZMIN, zmax = CASCADES_ZMAX;
#ifdef CASCADES_FROM_DEPTH
    // CASCADES_FROM_DEPTH: an expression (params.from_depth): 0 keeps the fixed range, as CSM.
    if (bool(CASCADES_FROM_DEPTH) && zbits.w[1] != 0u) {   // geometry seen; else the fixed range
        zmin = uintBitsToFloat(~zbits.w[0]);
        zmax = max(uintBitsToFloat(zbits.w[1]), zmin * 1.0001);   // a flat view: keep zmax > zmin
    }
    if (i == 0) {
        splits.z[0] = zmin;
        splits.z[1] = zmax;
        for (int k = 0; k <= n; ++k) splits.z[2 + k] = shadow_split(k, n, zmin, zmax, CASCADES_LAMBDA);
    }
#endif
    float z0 = shadow_split(i, n, zmin, zmax, CASCADES_LAMBDA);
    float z1 = shadow_split(i + 1, n, zmin, zmax, CASCADES_LAMBDA);
    float w = i + 1 < n ? CASCADES_BLEND * (z1 - z0) : 0.0;
    float prev_w = i > 0 ? CASCADES_BLEND * (z0 - shadow_split(i - 1, n, zmin, zmax, CASCADES_LAMBDA)) : 0.0;
    float from = max(z0 - prev_w, 1e-4);
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    for (int k = 0; k < 8; ++k) {
        vec3 p = view_corner((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? z1 : from);
        vec4 c = cameras.light.view_proj * vec4(p, 1.0);
        lo = min(lo, c.xy / c.w);
        hi = max(hi, c.xy / c.w);
    }
    // Square, so texels are square; clamped to the light's own box (nothing exists outside it).
    lo = max(lo, vec2(-1.0));
    hi = min(hi, vec2(1.0));
    vec2 centre = 0.5 * (lo + hi);
    float half_side = 0.5 * max(hi.x - lo.x, hi.y - lo.y);
    // ndc' = (ndc - centre) / half_side for x, y; z unchanged.
    mat4 crop = mat4(vec4(1.0 / half_side, 0, 0, 0), vec4(0, 1.0 / half_side, 0, 0), vec4(0, 0, 1, 0),
                     vec4(-centre / half_side, 0, 1));
    float light_height = 2.0 / abs(cameras.light.proj[1][1]);
    float texel = light_height * half_side / float(CASCADES_MAP);
    cascades_out.c[i] = ShadowCascade(crop * cameras.light.view_proj, vec4(from, z1, w, texel));
}
