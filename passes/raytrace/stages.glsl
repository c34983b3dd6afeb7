// DXR's ray-tracing stages mapped onto a compute shader (000_c9f7e5de708ecbb3.txt L5506-5741):
// lavapipe (Mesa 22.3) has neither VK_KHR_ray_tracing_pipeline nor ray queries, so the stages are
// GLSL functions and TraceRay is a loop over the instances through `raytrace/bvh.glsl`.
//
//   DXR                                   here
//   [shader("raygeneration")]             the compute shader's main(); one invocation per pixel,
//   DispatchRaysIndex / Dimensions          rt_launch_index() / the caller's image size
//   RayDesc { Origin, TMin, Direction, TMax }  RtRay (L5640-5646)
//   user payload struct (L5521-5539)      struct RtPayload, declared by the shader BEFORE this file
//   TraceRay(accel, flags, ..., ray, payload)  rt_trace_ray(ray, flags, payload)
//   [shader("closesthit")]                void rt_closest_hit(inout RtPayload, RtHitInfo)
//   [shader("miss")]                      void rt_miss(inout RtPayload, RtRay)
//   [shader("anyhit")] on opaque geometry  not run (all geometry is opaque, as with
//                                           RAY_FLAG_FORCE_OPAQUE); RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH
//                                           ends the search at the first hit found (pl_bvh_occluded):
//                                           the shadow ray of L5765-5770, "skip closest hit shader,
//                                           use miss shader"
//   acceleration structure (top level)    the shader's instances: rt_instance_count(),
//                                           rt_instance_mesh(i), rt_object_from_world(i) (the
//                                           inverse placement); bottom level = the host BVH per mesh
//   BuiltInTriangleIntersectionAttributes RtHitInfo.barycentrics: the hit is
//                                           (1 - x - y) v0 + x v1 + y v2 (L5551-5555)
//   InstanceID, PrimitiveIndex, RayTCurrent  RtHitInfo.instance, .prim, .t
//
// The shader provides, after including this file, the five functions declared below (GLSL allows
// a call before the body). With RT_BRUTE_FORCE defined to 1 every trace tests all triangles
// (pl_brute_closest): the same stages and callbacks, the reference traversal.
#ifndef PASSLAB_RAYTRACE_STAGES_GLSL
#define PASSLAB_RAYTRACE_STAGES_GLSL

#include "raytrace/bvh.glsl"

#ifndef RT_BRUTE_FORCE
#define RT_BRUTE_FORCE 0
#endif

// RayDesc (000 L5640-5646).
struct RtRay {
    vec3 origin;
    float tmin;  // a hit counts only for tmin < t < tmax
    vec3 direction;
    float tmax;
};

// Ray flags, DXR's values.
const uint RT_FLAG_NONE = 0u;
const uint RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH = 4u;
const uint RT_FLAG_SKIP_CLOSEST_HIT_SHADER = 8u;

// What the closest-hit stage sees: the intersection attributes and the system values.
struct RtHitInfo {
    vec2 barycentrics;  // (x, y): weights (1 - x - y, x, y) of the corners (000 L5551-5555)
    float t;            // RayTCurrent(): the world ray's parameter
    int instance;       // InstanceID(): the caller's instance index
    uint mesh;          // the mesh's index in the scene buffer's `meshes`
    uint prim;          // PrimitiveIndex(): the triangle in that mesh's index list
    vec3 origin;        // WorldRayOrigin()
    vec3 direction;     // WorldRayDirection() (as traced, not renormalised)
};

// The scene and the hit-group/miss "shaders": provided by the including shader.
int rt_instance_count();
uint rt_instance_mesh(int instance);
mat4 rt_object_from_world(int instance);
void rt_closest_hit(inout RtPayload payload, RtHitInfo hit);
void rt_miss(inout RtPayload payload, RtRay ray);

// Traversal cost of the invocation's traces so far (nodes visited + triangles tested, closest-hit
// traces only): a BVH that visits everything still agrees with brute force, but not in cost.
uint rt_work = 0u;

uvec2 rt_launch_index() { return gl_GlobalInvocationID.xy; }

// The closest hit over every instance (no stage called): the query TraceRay starts with.
PlHit rt_closest(RtRay ray) {
    PlHit hit = pl_no_hit(ray.tmax);
    for (int i = 0; i < rt_instance_count(); ++i) {
#if RT_BRUTE_FORCE
        pl_brute_closest(rt_instance_mesh(i), rt_object_from_world(i), i, ray.origin, ray.direction, ray.tmin, hit);
#else
        pl_bvh_closest(rt_instance_mesh(i), rt_object_from_world(i), i, ray.origin, ray.direction, ray.tmin, hit);
#endif
    }
    rt_work += hit.nodes + hit.tests;
    return hit;
}

// Whether anything lies on the open segment (tmin, tmax): the first hit found ends the search.
bool rt_any(RtRay ray) {
#if RT_BRUTE_FORCE
    return rt_closest(ray).instance >= 0;
#else
    for (int i = 0; i < rt_instance_count(); ++i)
        if (pl_bvh_occluded(rt_instance_mesh(i), rt_object_from_world(i), ray.origin, ray.direction, ray.tmin, ray.tmax))
            return true;
    return false;
#endif
}

// TraceRay: traverse, then run the closest-hit stage on the closest hit or the miss stage.
// With RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH the first hit ends the traversal; such a hit is
// not the closest, so it is only useful with RT_FLAG_SKIP_CLOSEST_HIT_SHADER (shadow rays: "if
// ray misses -> not in shadow; skip closest hit shader; use miss shader", 000 L5765-5770).
void rt_trace_ray(RtRay ray, uint flags, inout RtPayload payload) {
    if ((flags & RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH) != 0u && (flags & RT_FLAG_SKIP_CLOSEST_HIT_SHADER) != 0u) {
        if (!rt_any(ray)) rt_miss(payload, ray);
        return;
    }
    PlHit hit = rt_closest(ray);
    if (hit.instance < 0) {
        rt_miss(payload, ray);
        return;
    }
    if ((flags & RT_FLAG_SKIP_CLOSEST_HIT_SHADER) != 0u) return;
    rt_closest_hit(payload, RtHitInfo(hit.bary, hit.t, hit.instance, hit.mesh, hit.prim, ray.origin, ray.direction));
}

#endif
