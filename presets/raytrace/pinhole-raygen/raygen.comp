#version 450
// pinhole-raygen: the seed's complete DXR example (000_c9f7e5de708ecbb3.txt L5618-5677) in
// compute: a pinhole camera's ray generation, one TraceRay per pixel, a closest-hit stage that
// paints red and a miss stage that paints blue. The stages are raytrace/stages.glsl, the ray
// raytrace/pinhole.glsl (the exercise's file).
//
// The listing's typo, fixed: SimpleRayPayload declares `rayColor` (L5533) but the raygen writes
// `payload.color` (L5651) and the hit/miss shaders set `data.color` (L5663, L5671): one name,
// `color`, here.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba8) writeonly uniform image2D color;   // the picture: exactly red or blue
layout(rgba32f) writeonly uniform image2D dirs;  // xyz = the pixel's ray direction (tests read it)

struct RtPayload {
    vec3 color;  // "keep the ray payload as small as possible" (L5523-5526): 12 bytes
};

#include "raytrace/stages.glsl"
#include "raytrace/pinhole.glsl"

// The scene: one instance of the sphere (mesh 0 of `scene`) at params.sphere_at.
int rt_instance_count() { return 1; }
uint rt_instance_mesh(int instance) { return 0u; }
mat4 rt_object_from_world(int instance) { return mat4(vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0), vec4(-params.sphere_at, 1)); }

// [shader("closesthit")] RayClosestHit (L5657-5664): red.
void rt_closest_hit(inout RtPayload payload, RtHitInfo hit) { payload.color = vec3(1.0, 0.0, 0.0); }

// [shader("miss")] RayMiss (L5666-5672): blue.
void rt_miss(inout RtPayload payload, RtRay ray) { payload.color = vec3(0.0, 0.0, 1.0); }

// [shader("raygeneration")] PinholeCamera (L5618-5652).
void main() {
    uvec2 pix = rt_launch_index(), dims = uvec2(imageSize(color));   // DispatchRaysIndex / Dimensions
    if (any(greaterThanEqual(pix, dims))) return;
    RtRay ray = rt_pinhole_ray(rt_pinhole_camera(), pix, dims);
    RtPayload payload = RtPayload(vec3(0.0));                          // L5632
    rt_trace_ray(ray, RT_FLAG_NONE, payload);                          // L5633-5641, mask 0xFF: every instance
    imageStore(color, ivec2(pix), vec4(payload.color, 1.0));           // L5651
    imageStore(dirs, ivec2(pix), vec4(ray.direction, 0.0));
}
