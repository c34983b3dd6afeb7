#version 450
// Any-hit queries checked against the brute-force closest hit of the same ray (read from
// `closest`): a ray that hits at t is occluded on (0, t * (1 + 1e-6)) and not on (0, t) (no
// triangle is closer than the closest); a ray that misses is never occluded. Writes the number
// of disagreements (0, 1 or 2) per texel; the test requires 0 everywhere.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) readonly uniform image2D closest;
layout(r32f) writeonly uniform image2D errors;

#include "scene.glsl"

bool occluded(vec3 ro, vec3 rd, float tmax) {
    for (int i = 0; i < INSTANCE_COUNT; ++i) {
        Placement p = placement(i);
        if (pl_bvh_occluded(p.mesh, object_from_world(p), ro, rd, 0.0, tmax)) return true;
    }
    return false;
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(errors)))) return;
    vec3 ro, rd;
    ray_of(px, ro, rd);
    vec4 c = imageLoad(closest, px);
    int wrong = 0;
    if (c.x >= 0.0) {
        wrong += occluded(ro, rd, c.y * (1.0 + 1e-6)) ? 0 : 1;
        wrong += occluded(ro, rd, c.y) ? 1 : 0;
    } else {
        wrong += occluded(ro, rd, 1e30) ? 1 : 0;
    }
    imageStore(errors, px, vec4(float(wrong)));
}
