#version 450
// Forward shading of many lights, the variants of 003_cfc3b5b225ddab3d.txt L586-798, all with
// the same Lambert + normalised Blinn-Phong per light (passes/deferred/lights.glsl):
//   LOOP, method naive  (L586-613): every light at every fragment, O(F x L) evaluations.
//   LOOP, method culled (L632-661): "if (this fragment is illuminated by current light)" —
//        the predicate is still evaluated for all F x L pairs; only the shading is skipped.
//   BATCH = N (L701-789, option 1): the object's light list (lists.comp) with a shader
//        specialised for exactly N lights: a fixed-count loop, no per-light test; the list is
//        padded to N with kNoLight, which shades as a black light (branch-free).
//   ONE_LIGHT (L770, L790-798, option 2): one pass per light, additive blending; the pass
//        draws only the objects in that light's list.
// `missing` (BATCH only; tests): x = lights contributing > 1/1024 that the object's list lacks,
// y = lights the verification looked at (params.lights on geometry): a verification loop that
// does not run would report 0 missing and pass, so the test probes y too.
#include "deferred/lights.glsl"
#include "object_lists.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec4 v_material;
layout(location = 3) flat in int v_object;
layout(location = 0) out vec4 lit;
#ifdef BATCH
layout(location = 1) out vec2 missing;
#endif
layout(std430) readonly buffer object_lights { uint list_words[]; };
const float kShininess = 32.0;

vec3 one_light(int i, vec3 n, vec3 v) {
    return shade_point_light(point_light(i, frame.time), v_world, n, v, v_material.rgb, v_material.a, kShininess);
}

void main() {
    vec3 n = normalize(v_normal), v = normalize(frame.camera_pos.xyz - v_world);
    uint base = uint(v_object * kListWords), count = list_words[base];
#ifdef ONE_LIGHT
    lit = vec4(one_light(pl_iteration, n, v), 0.0);  // added to the base pass's ambient
    if (params.show == SHOW_COUNT) lit = vec4(0.0);
    return;
#else
    vec3 c = params.ambient * v_material.rgb;
#ifdef LOOP
    for (int i = 0; i < params.lights; ++i) {
        if (params.method == METHOD_CULLED) {
            PointLight l = point_light(i, frame.time);
            vec3 to_light = l.position - v_world;
            bool illuminated = dot(to_light, to_light) < l.radius * l.radius && dot(n, to_light) > 0.0;
            if (!illuminated) continue;
        }
        c += one_light(i, n, v);
    }
#else  // BATCH
    for (int k = 0; k < BATCH; ++k) {
        uint idx = list_words[base + 1u + uint(k)];
        PointLight l = point_light(int(idx & 63u), frame.time);
        l.color *= idx == kNoLight ? 0.0 : 1.0;
        c += shade_point_light(l, v_world, n, v, v_material.rgb, v_material.a, kShininess);
    }
    missing = vec2(0.0);
    for (int i = 0; params.verify && i < params.lights; ++i) {
        missing.y += 1.0;
        vec3 e = one_light(i, n, v);
        if (max(e.r, max(e.g, e.b)) <= 1.0 / 1024.0) continue;
        bool listed = false;
        for (uint k = 0u; k < count; ++k) listed = listed || list_words[base + 1u + k] == uint(i);
        missing.x += listed ? 0.0 : 1.0;
    }
#endif
    if (params.show == SHOW_COUNT) c = light_count_heat(float(count) / 64.0);
    lit = vec4(c, 1.0);
#endif
}
