#version 450
// Forward shading over the fragment's cluster list (the "forward" half of clustered forward):
// the cluster from the fragment's tile and view depth, then the same Lambert + normalised
// Blinn-Phong per light as every deferred preset (passes/deferred/lights.glsl), for the
// listed lights only. Opaque and transparent surfaces shade alike: the clusters cover the
// whole frustum, not the depth buffer's samples (tiled deferred's tile bounds would miss the
// glass pane in front of the floor).
// BRUTE_FORCE: every light instead (the reference). PANE: the glass, blended with kPaneAlpha.
// `missing` (tests): lights reaching this fragment by more than 1/1024 but not in its list.
// NO_STATS (the live passes): lit alone, without `missing` (a 4x MSAA rg32f target less to write).
#include "deferred/lights.glsl"
#include "clusters.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec4 v_material;
layout(location = 0) out vec4 lit;
#if !defined(BRUTE_FORCE) && !defined(NO_STATS)
layout(location = 1) out vec2 missing;  // x: contributing lights not listed, y: list length
#endif
layout(std430) readonly buffer cluster_count { uint counts[]; };
layout(std430) readonly buffer cluster_lights { uint slots[]; };
const float kShininess = 32.0;
const float kPaneAlpha = 0.35;

void main() {
#ifdef PANE
    float alpha = kPaneAlpha;
#else
    float alpha = 1.0;
#endif
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);  // the pane is two-sided
    vec3 v = normalize(frame.camera_pos.xyz - v_world);
    float d = -(frame.view * vec4(v_world, 1.0)).z;
    ivec3 cc = cluster_of(gl_FragCoord.xy, d);
    uint c = uint(cluster_index(cc)), count = min(counts[c], uint(kMaxPerCluster)), base = c * uint(kMaxPerCluster);
    vec3 col = params.ambient * v_material.rgb;
#ifdef BRUTE_FORCE
    for (int i = 0; i < params.lights; ++i) col += shade_point_light(point_light(i, frame.time), v_world, n, v, v_material.rgb, v_material.a, kShininess);
#else
    for (uint k = 0u; k < count; ++k)
        col += shade_point_light(point_light(int(slots[base + k]), frame.time), v_world, n, v, v_material.rgb, v_material.a, kShininess);
#ifndef NO_STATS
    missing = vec2(0.0, float(count));
    for (int i = 0; params.verify && i < params.lights; ++i) {
        vec3 e = shade_point_light(point_light(i, frame.time), v_world, n, v, v_material.rgb, v_material.a, kShininess);
        if (max(e.r, max(e.g, e.b)) > 1.0 / 1024.0) {
            bool listed = false;
            for (uint k = 0u; k < count; ++k) listed = listed || slots[base + k] == uint(i);
            missing.x += listed ? 0.0 : 1.0;
        }
    }
#endif
    if (params.show == SHOW_COUNT) col = count == 0u ? vec3(0.0) : light_count_heat(float(count) / 64.0);
    if (params.show == SHOW_SLICES) col = (0.35 + 0.65 * fract(float(cc.z) * 0.618034 + vec3(0.0, 0.33, 0.67))) * (0.3 + 0.7 * max(dot(n, normalize(vec3(0.3, 1.0, 0.2))), 0.0));
#endif
    lit = vec4(col, alpha);
}
