#version 450
// Test-only: the silhouette edges counted without adjacency, from the host-built triangle list
// (buffer generator = "triangles": every triangle's corners): for each front-facing triangle and
// each of its edges (a, b), search all triangles for the one holding b -> a, and apply the same
// predicate (npr/silhouette.glsl) to it as (b, a, o). O(n^2): 2304 x 3 x 2304 tests.
// `fins.brute` = the count; `fins.diff` = emitted - brute (0 when the GS found the same edges).
layout(local_size_x = 64) in;
#include "raytrace/bvh.glsl"
#include "npr/silhouette.glsl"
layout(std430) buffer Fins { uint emitted; uint brute; int diff; } fins;
void main() {
    uint t = gl_GlobalInvocationID.x;
    PlSceneMesh m = pl_scene_mesh(0u);
    if (t >= m.triangle_count) return;
    PlSceneTriangle tri = pl_scene_triangle(m.triangle_offset + t);
    vec3 v[3] = vec3[](tri.v0, tri.v1, tri.v2);
    if (!faces_eye(v[0], v[1], v[2], 0.0)) return;
    for (int e = 0; e < 3; ++e) {
        vec3 a = v[e], b = v[(e + 1) % 3];
        for (uint u = 0u; u < m.triangle_count; ++u) {
            PlSceneTriangle q = pl_scene_triangle(m.triangle_offset + u);
            vec3 w[3] = vec3[](q.v0, q.v1, q.v2);
            for (int k = 0; k < 3; ++k) {
                // The edge, reversed. Corners match within 1e-5: the torus's seam duplicates
                // vertices whose positions differ in the last bits (the adjacency list welds them).
                if (distance(w[k], b) < 1e-5 && distance(w[(k + 1) % 3], a) < 1e-5) {
                    if (!faces_eye(b, a, w[(k + 2) % 3], 0.0)) atomicAdd(fins.brute, 1u);
                }
            }
        }
    }
}
