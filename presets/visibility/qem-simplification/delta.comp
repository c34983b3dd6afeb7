#version 450
// The quadric error metric, evaluated on the GPU for the meshes the host simplified
// (host/scene/simplify.cpp builds them with the same metric; this shader recomputes it as the
// seed writes it, 000_c9f7e5de708ecbb3.txt L6004-6033):
//
//   plane of a face  p = [A B C D], Ax + By + Cz + D = 0 with |(A,B,C)| = 1      (L6008-6010)
//   distance         p^T v, v = [x y z 1]^T                                         (L6011-6012)
//   Delta(v) = sum_p (p^T v)^2 = v^T (sum_p p p^T) v = v^T Q v                      (L6019-6025)
//   p p^T = [A^2 AB AC AD; AB B^2 BC BD; AC BC C^2 CD; AD BD CD D^2]                (L6027-6030)
//   an edge collapse v1 + v2 just adds Q1 + Q2                                      (L6033)
//
// One thread per corner v of the simplified mesh SIMPLE: Q = sum of w p p^T over the faces of
// the full mesh FULL whose centroid lies within RADIUS of v (the faces that were merged into v's
// neighbourhood), w = face area as in the host (the cost measures the surface, not the
// tessellation). Delta(v) = v^T Q v is a sum of squares, so it is >= 0; sqrt(Delta / sum w) is
// the area-weighted RMS distance from v to those planes (docs/format.md, the host's error).
// For the plane (every face on one plane) Delta is exactly 0: collapsing inside a planar region
// costs nothing.
layout(local_size_x = 64) in;
#include "raytrace/bvh.glsl"
#include "qem.glsl"
layout(std430) buffer Delta {
    uint triangles[4];   // per mesh of the scene buffer: its triangle count
    float pad_[4];
    float delta[N];      // v^T Q v per corner of SIMPLE
    float rms[N];        // sqrt(Delta / sum w) per corner
    float planar[N];     // v^T Q v per corner of PLANE_LOD against PLANE_FULL's faces
} result;

// Q of one face, the 10 distinct entries of the symmetric 4x4 p p^T scaled by w.
struct Quadric { float a2, ab, ac, ad, b2, bc, bd, c2, cd, d2; };

Quadric face_quadric(vec3 v0, vec3 v1, vec3 v2) {
    vec3 c = cross(v1 - v0, v2 - v0);
    float len = length(c);
    Quadric q = Quadric(0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    if (len == 0.0) return q;                 // zero-area face: no plane, no weight
    vec3 n = c / len;                         // |(A,B,C)| = 1: p^T v is a distance
    float d = -dot(n, v0);                    // D: the plane passes through the face
    float w = 0.5 * len;                      // area weight
    q.a2 = w * n.x * n.x; q.ab = w * n.x * n.y; q.ac = w * n.x * n.z; q.ad = w * n.x * d;
    q.b2 = w * n.y * n.y; q.bc = w * n.y * n.z; q.bd = w * n.y * d;
    q.c2 = w * n.z * n.z; q.cd = w * n.z * d;
    q.d2 = w * d * d;
    return q;
}

void add(inout Quadric q, Quadric f) {        // Q1 + Q2 (L6033)
    q.a2 += f.a2; q.ab += f.ab; q.ac += f.ac; q.ad += f.ad; q.b2 += f.b2;
    q.bc += f.bc; q.bd += f.bd; q.c2 += f.c2; q.cd += f.cd; q.d2 += f.d2;
}

// The sandwich product v^T Q v with v = [x y z 1].
float sandwich(Quadric q, vec3 v) {
    return q.a2 * v.x * v.x + q.b2 * v.y * v.y + q.c2 * v.z * v.z + q.d2
         + 2.0 * (q.ab * v.x * v.y + q.ac * v.x * v.z + q.bc * v.y * v.z)
         + 2.0 * (q.ad * v.x + q.bd * v.y + q.cd * v.z);
}

// Q of the faces of mesh `full` near v (and their total weight), all placed as rendered.
Quadric gather(uint full, vec3 v, bool floor_plane, out float weight) {
    PlSceneMesh m = pl_scene_mesh(full);
    Quadric q = Quadric(0, 0, 0, 0, 0, 0, 0, 0, 0, 0);
    weight = 0.0;
    for (uint j = m.triangle_offset; j < m.triangle_offset + m.triangle_count; ++j) {
        PlSceneTriangle t = pl_scene_triangle(j);
        vec3 a = place(t.v0, floor_plane), b = place(t.v1, floor_plane), c = place(t.v2, floor_plane);
        if (distance((a + b + c) / 3.0, v) > RADIUS) continue;
        add(q, face_quadric(a, b, c));
        weight += 0.5 * length(cross(b - a, c - a));
    }
    return q;
}

vec3 corner(PlSceneTriangle t, uint k) { return k == 0u ? t.v0 : k == 1u ? t.v1 : t.v2; }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < 4u) result.triangles[i] = pl_scene_mesh(i).triangle_count;
    PlSceneMesh s = pl_scene_mesh(SIMPLE);
    if (i < s.triangle_count * 3u && i < uint(N)) {
        vec3 v = corner(pl_scene_triangle(s.triangle_offset + i / 3u), i % 3u);
        float w;
        Quadric q = gather(FULL, v, false, w);
        float delta = sandwich(q, v);
        result.delta[i] = delta;
        result.rms[i] = w > 0.0 ? sqrt(max(delta, 0.0) / w) : 0.0;
    }
    PlSceneMesh p = pl_scene_mesh(PLANE_LOD);
    if (i < p.triangle_count * 3u && i < uint(N)) {
        vec3 v = place(corner(pl_scene_triangle(p.triangle_offset + i / 3u), i % 3u), true);
        float w;
        result.planar[i] = sandwich(gather(PLANE_FULL, v, true, w), v);
    }
}
