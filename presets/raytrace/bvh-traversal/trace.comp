#version 450
// bvh-traversal: one primary ray per pixel through the host-built BVH of each instance
// (raytrace/bvh.glsl: the stackless skip-list walk of 002_644d46bdce7e5305.txt L2104-2129 with the
// slab test of L1996-2015), or with RT_BRUTE_FORCE = 1 over every triangle: the same ray
// generation, the same closest-hit and miss stages, only the traversal differs.
//
// out_hits = (instance, t, prim, work): the closest hit's instance (-1 = miss), its ray parameter,
// the triangle in its mesh's index list (-1 = miss) and the traversal's cost (nodes visited +
// triangles tested). out_pos = (world position of the hit, instance) for the picture.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) writeonly uniform image2D out_hits;
layout(rgba32f) writeonly uniform image2D out_pos;

// The payload: what the closest hit reports (DXR's InstanceID, RayTCurrent, PrimitiveIndex).
struct RtPayload {
    float instance, t, prim;
};

#include "scene.glsl"

void rt_closest_hit(inout RtPayload payload, RtHitInfo hit) { payload = RtPayload(float(hit.instance), hit.t, float(hit.prim)); }
void rt_miss(inout RtPayload payload, RtRay ray) { payload = RtPayload(-1.0, -1.0, -1.0); }

void main() {
    uvec2 pix = rt_launch_index(), dims = uvec2(imageSize(out_hits));
    if (any(greaterThanEqual(pix, dims))) return;
#ifdef BRUTE_SLICES
    // The reference is ~1000 times the walk's cost: frame f traces the rows y = f (mod
    // BRUTE_SLICES) only, so no frame comes near the 20 s watchdog; the image keeps the other rows.
    if (pix.y % uint(BRUTE_SLICES) != uint(frame.index) % uint(BRUTE_SLICES)) return;
#endif
    RtRay ray = rt_pinhole_ray(rt_pinhole_camera(), pix, dims);
    RtPayload payload = RtPayload(-1.0, -1.0, -1.0);
    rt_trace_ray(ray, RT_FLAG_NONE, payload);
    imageStore(out_hits, ivec2(pix), vec4(payload.instance, payload.t, payload.prim, float(rt_work)));
    vec3 p = payload.instance < 0.0 ? vec3(0.0) : ray.origin + payload.t * ray.direction;
    imageStore(out_pos, ivec2(pix), vec4(p, payload.instance));
}
