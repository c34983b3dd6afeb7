#version 450
// The deferred scene (passes/deferred/objects.glsl) for every pass of this preset, with the
// selection each method needs. The shading passes test depth `equal` against the base pass,
// so every pass computes gl_Position by the same expression before any selection (the
// `invariant` qualifier would say so, but glslang puts it on a block member, which SPIR-V
// validation rejects).
//   BATCH     only objects whose list length calls for exactly this specialised shader
//   PER_LIGHT only objects that the pass's light (pl_iteration) illuminates
// Hidden objects are sent outside the clip volume. (Which passes run at all, the chosen
// method's, is the passes' `enabled` expression in preset.toml.)
#include "deferred/objects.glsl"
#include "object_lists.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec4 v_material;
layout(location = 3) flat out int v_object;
layout(std430) readonly buffer object_lights { uint list_words[]; };
layout(std430) readonly buffer object_masks { uint mask_words[]; };

void main() {
#ifdef FLOOR
    int object = 0;
    vec3 p = position;
    v_material = kFloorMaterial;
#else
    int object = 1 + gl_InstanceIndex;
    SceneBall b = scene_ball(gl_InstanceIndex);
    vec3 p = position * b.scale + b.centre;
    v_material = b.material;
#endif
    v_world = p;
    v_normal = normal;
    v_object = object;
    gl_Position = frame.view_proj * vec4(p, 1.0);
    bool visible = true;
#ifdef BATCH
    visible = visible && batch_of(list_words[object * kListWords]) == BATCH;
#endif
#ifdef PER_LIGHT
    visible = visible && (mask_words[2 * object + pl_iteration / 32] & (1u << uint(pl_iteration % 32))) != 0u;
#endif
    if (!visible) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
