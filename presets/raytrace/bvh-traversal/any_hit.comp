#version 450
// bvh-traversal's check of the any-hit path (TraceRay with RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH
// | RT_FLAG_SKIP_CLOSEST_HIT_SHADER, the shadow query: the first triangle found ends the search)
// against the brute-force closest hit of the same primary ray: a ray that hits at t is occluded on
// (0, t (1 + 1e-6)) and not on (0, t) (no triangle is nearer than the nearest); a ray that misses
// is never occluded. Writes the number of disagreements (0, 1 or 2) per pixel.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D closest;   // the brute-force hits: (instance, t, triangle, work)
layout(r32f) writeonly uniform image2D errors;

struct RtPayload {
    bool missed;  // set by the miss stage; the closest-hit stage does not run
};

#include "scene.glsl"

void rt_closest_hit(inout RtPayload payload, RtHitInfo hit) {}
void rt_miss(inout RtPayload payload, RtRay ray) { payload.missed = true; }

bool occluded(RtRay ray, float tmax) {
    ray.tmax = tmax;
    RtPayload payload = RtPayload(false);
    rt_trace_ray(ray, RT_FLAG_ACCEPT_FIRST_HIT_AND_END_SEARCH | RT_FLAG_SKIP_CLOSEST_HIT_SHADER, payload);
    return !payload.missed;
}

void main() {
    uvec2 pix = rt_launch_index(), dims = uvec2(imageSize(errors));
    if (any(greaterThanEqual(pix, dims))) return;
    RtRay ray = rt_pinhole_ray(rt_pinhole_camera(), pix, dims);
    vec4 c = texelFetch(closest, ivec2(pix), 0);
    int wrong = 0;
    if (c.x >= 0.0) {
        wrong += occluded(ray, c.y * (1.0 + 1e-6)) ? 0 : 1;
        wrong += occluded(ray, c.y) ? 1 : 0;
    } else {
        wrong += occluded(ray, ray.tmax) ? 1 : 0;
    }
    imageStore(errors, ivec2(pix), vec4(float(wrong)));
}
