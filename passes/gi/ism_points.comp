#version 450
// The point cloud of the imperfect shadow maps (000 L5243-5244: "coarse approximation of scene
// as point cloud, limited number of points"): point i is area-uniform over the box's surfaces,
//   surface k with probability A_k / A (inverse CDF over the 15 sampled surfaces),
//   then (u, v) uniform in the plane's [-1,1]^2, placed by the surface's world_from_object,
// from a hash of i alone (deterministic). VPL s later uses points s, s + slots, ... (ism_splat.vert).
layout(local_size_x = 64) in;
#include "gi/ism.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(ism_points.p.length())) return;
    uint state = i * 0x9e3779b9u + 0x2545f491u;  // the seed: the point's index
    float pick = ism_rand(state) * ism_total_area();
    int k = 0;
    for (; k < VPL_SURFACES - 1; ++k) {
        pick -= ism_area(k);
        if (pick < 0.0) break;
    }
    if (!ism_sampled(k)) k = 0;  // only reachable through rounding at the top of the CDF
    vec2 uv = vec2(ism_rand(state), ism_rand(state)) * 2.0 - 1.0;
    mat4 m = vpl_surface(k);
    vec3 p = (m * vec4(uv.x, 0.0, uv.y, 1.0)).xyz;
    ism_points.p[i] = IsmPoint(vec4(p, float(k)), vec4(normalize(m[1].xyz), 0.0));
}
