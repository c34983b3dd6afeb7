#version 450
// One ray per texel (scene.glsl), closest hit over every instance: through the BVH, or with
// BRUTE = 1 over every triangle. Writes (instance, t, prim, work) with work = nodes visited +
// triangles tested; instance, t and prim are -1 on a miss.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) writeonly uniform image2D out_hits;

#include "scene.glsl"

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(out_hits)))) return;
    vec3 ro, rd;
    ray_of(px, ro, rd);
    PlHit hit = pl_no_hit(1e30);
    for (int i = 0; i < INSTANCE_COUNT; ++i) {
        Placement p = placement(i);
#if BRUTE
        pl_brute_closest(p.mesh, object_from_world(p), i, ro, rd, 0.0, hit);
#else
        pl_bvh_closest(p.mesh, object_from_world(p), i, ro, rd, 0.0, hit);
#endif
    }
    bool found = hit.instance >= 0;
    imageStore(out_hits, px, vec4(float(hit.instance), found ? hit.t : -1.0, found ? float(hit.prim) : -1.0, float(hit.nodes + hit.tests)));
}
