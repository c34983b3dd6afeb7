// Ray queries into the patch scene of gi/radiosity_patches.glsl, through the host BVH
// (raytrace/bvh.glsl; the graph's buffer `scene` = { generator = "bvh", meshes = ["wall", "block"] }).
// `walls` is 5 for the Cornell box (open towards the camera) or 6 for the closed box.
#ifndef PASSLAB_GI_RADIOSITY_TRACE_GLSL
#define PASSLAB_GI_RADIOSITY_TRACE_GLSL

#include "gi/radiosity_patches.glsl"
#include "raytrace/bvh.glsl"

// Instance ids in PlHit: walls 0..walls-1, blocks RAD_BLOCK_ID + b (fixed, so the closed front
// wall does not renumber the blocks).
const int RAD_BLOCK_ID = RAD_WALLS;

// The first surface along (ro, rd): whether it hit, t, the surface (radiosity_patches.glsl), the
// object-space hit point, and whether the ray arrived from behind (it started inside a block).
struct RadHit {
    bool found;
    float t;
    int surface;
    vec3 object_point;
    bool back;
};

RadHit radiosity_trace(vec3 ro, vec3 rd, int walls) {
    PlHit hit = pl_no_hit(1e30);
    for (int i = 0; i < walls; ++i) pl_bvh_closest(0u, inverse(radiosity_wall(i)), i, ro, rd, 1e-4, hit);
    for (int b = 0; b < CORNELL_BLOCKS; ++b) pl_bvh_closest(1u, inverse(cornell_block(b)), RAD_BLOCK_ID + b, ro, rd, 1e-4, hit);
    if (hit.instance < 0) return RadHit(false, hit.t, -1, vec3(0.0), false);
    int mesh = hit.instance < RAD_BLOCK_ID ? 0 : 1;
    int instance = mesh == 0 ? hit.instance : hit.instance - RAD_BLOCK_ID;
    mat4 world_from_object = mesh == 0 ? radiosity_wall(instance) : cornell_block(instance);
    vec3 o = (inverse(world_from_object) * vec4(ro + hit.t * rd, 1.0)).xyz;
    int surface = radiosity_surface_of_hit(mesh, instance, o);
    return RadHit(true, hit.t, surface, o, dot(rd, radiosity_world_normal(radiosity_surface(surface))) > 0.0);
}

// The patch the ray (ro, rd) hits first; -1 when it leaves the scene, -2 when it hits a surface
// from behind (the ray started inside a block).
int radiosity_trace_patch(vec3 ro, vec3 rd, int walls) {
    RadHit h = radiosity_trace(ro, rd, walls);
    if (!h.found) return -1;
    if (h.back) return -2;
    RadSurface s = radiosity_surface(h.surface);
    return radiosity_patch_at(s, radiosity_surface_coords(s, h.object_point));
}

// Whether the segment from p to q is blocked (shadow rays towards the spot light).
bool radiosity_occluded(vec3 p, vec3 q, int walls) {
    vec3 d = q - p;
    for (int i = 0; i < walls; ++i)
        if (pl_bvh_occluded(0u, inverse(radiosity_wall(i)), p, d, 1e-4, 0.9999)) return true;
    for (int b = 0; b < CORNELL_BLOCKS; ++b)
        if (pl_bvh_occluded(1u, inverse(cornell_block(b)), p, d, 1e-4, 0.9999)) return true;
    return false;
}

#endif
