#version 450
// The tetrahedralisation of the probe lattice (gi/tetrahedral_probes.glsl): tetrahedron 6c + k of
// cell c is the Kuhn simplex of permutation k, the path from the cell's corner (0,0,0) to (1,1,1)
// stepping along the axes in the order perm[k]. The 6 paths share the main diagonal and fill the
// cube; neighbouring cells split their shared face along the same diagonal, so the tetrahedra
// meet face to face (a valid tessellation, no T-junctions). Each tetrahedron also stores the
// inverse of its edge matrix [v0 - v3, v1 - v3, v2 - v3] and v3, so a lookup is one product.
layout(local_size_x = 64) in;

#include "gi/tetrahedral_probes.glsl"

layout(std430) writeonly buffer Tets { ivec4 rec[]; } tets;

void main() {
    int t = int(gl_GlobalInvocationID.x);
    if (t >= TP_TETS) return;
    int cell = t / 6, k = t % 6;
    ivec3 base = ivec3(cell % (TP_N - 1), (cell / (TP_N - 1)) % (TP_N - 1), cell / ((TP_N - 1) * (TP_N - 1)));
    const ivec3 perm[6] = TP_PERM;
    ivec3 p = base;
    ivec4 v;
    v.x = tetrahedral_probe_index(p);
    p[perm[k].x] += 1;
    v.y = tetrahedral_probe_index(p);
    p[perm[k].y] += 1;
    v.z = tetrahedral_probe_index(p);
    p[perm[k].z] += 1;
    v.w = tetrahedral_probe_index(p);
    vec3 p0 = tetrahedral_probe_position(v.x), p1 = tetrahedral_probe_position(v.y);
    vec3 p2 = tetrahedral_probe_position(v.z), p3 = tetrahedral_probe_position(v.w);
    mat3 inv = inverse(mat3(p0 - p3, p1 - p3, p2 - p3));
    tets.rec[5 * t] = v;
    tets.rec[5 * t + 1] = ivec4(floatBitsToInt(inv[0]), 0);
    tets.rec[5 * t + 2] = ivec4(floatBitsToInt(inv[1]), 0);
    tets.rec[5 * t + 3] = ivec4(floatBitsToInt(inv[2]), 0);
    tets.rec[5 * t + 4] = ivec4(floatBitsToInt(p3), 0);
}
