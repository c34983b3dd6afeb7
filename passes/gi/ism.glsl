// Imperfect shadow maps (Ritschel et al. 2008; 000_c9f7e5de708ecbb3.txt L5227-5322): "VPL
// approaches do not require accurate geometry" (L5229), so each VPL's paraboloid shadow map
// (L5242, "parabolic (omnidirectional) shadow map") is splatted from a "coarse approximation of
// scene as point cloud" with a "limited number of points" (L5243-5244), and the holes between
// the points are filled by pull-push (L5258-5273, "pull-push hole filling").
//
// The point set: ism_count() = points_per_vpl * slots points, area-uniform over the box's
// surfaces (gi/vpl.glsl's 17 surfaces minus the two block bottoms, which lie on the floor).
// VPL s uses the interleaved subset s, s + slots, s + 2 slots, ... (each subset is itself an
// area-uniform sample of the scene, so every VPL sees the whole box, coarsely). Shared by
// ism_points.comp, ism_splat.vert and the tests' ism_match.comp.
#ifndef PASSLAB_GI_ISM_GLSL
#define PASSLAB_GI_ISM_GLSL
#include "gi/vpl.glsl"

// Point i: its world position (w: the surface 0..16 it lies on) and that surface's normal.
struct IsmPoint { vec4 position; vec4 normal; };
layout(std430) buffer IsmPoints { IsmPoint p[]; } ism_points;

// A block's face 3 (-Y) lies on the floor: never visible, no points.
bool ism_sampled(int k) { return k < CORNELL_WALLS || (k - CORNELL_WALLS) % 6 != 3; }

// Area of surface k: the plane of size 2 is [-1,1]^2 in XZ, so 4 |M x  x  M z|.
float ism_area(int k) {
    mat4 m = vpl_surface(k);
    return ism_sampled(k) ? 4.0 * length(cross(m[0].xyz, m[2].xyz)) : 0.0;
}

float ism_total_area() {
    float a = 0.0;
    for (int k = 0; k < VPL_SURFACES; ++k) a += ism_area(k);
    return a;  // 5 walls x 4 + short block 5 x 0.36 + tall block (0.36 + 4 x 0.72) = 25.04
}

// The radius of the disc each point of one VPL's subset stands for: n points share the area A,
// r = sqrt(A / (pi n)).
float ism_point_radius(float points_per_vpl) { return sqrt(ism_total_area() / (3.14159265 * points_per_vpl)); }

// A 32-bit integer hash (Wellons' lowbias32, the same as gi/vpl_trace.glsl's vpl_hash, which
// needs the BVH buffer): deterministic, seeded by the point's index.
uint ism_hash(uint x) {
    x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
    return x;
}
float ism_rand(inout uint state) { state = ism_hash(state); return float(state >> 8) * (1.0 / 16777216.0); }
#endif
