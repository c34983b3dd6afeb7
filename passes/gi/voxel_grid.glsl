// The voxel grid of presets/gi/voxel-gi: VX_N^3 cells over [-VX_EXTENT, VX_EXTENT]^3, the Cornell
// box [-1, 1]^3 with a margin, and the conservative triangle/box overlap test that decides which
// cells a triangle marks. The margin matters: with the grid exactly on the box, the walls lay on
// the grid's outer faces and the rotations' rounding (cos(pi / 2) = -4e-8) put parts of them just
// outside, unmarked (the upper half of the side walls was missing from the voxels).
#ifndef PASSLAB_GI_VOXEL_GRID_GLSL
#define PASSLAB_GI_VOXEL_GRID_GLSL

#define VX_N 64
const float VX_EXTENT = 1.0625;
const float VX_SIZE = 2.0 * VX_EXTENT / float(VX_N);

vec3 voxel_lo(ivec3 c) { return vec3(-VX_EXTENT) + vec3(c) * VX_SIZE; }
ivec3 voxel_of(vec3 x) { return clamp(ivec3(floor((x + VX_EXTENT) / VX_SIZE)), ivec3(0), ivec3(VX_N - 1)); }
vec3 voxel_uvw(vec3 x) { return (x + VX_EXTENT) / (2.0 * VX_EXTENT); }

// Does triangle (a, b, c) touch the box centre +- h? The separating axis theorem (Akenine-Moller
// 2001): the two do not overlap iff one of 13 axes separates them: the box's 3 face normals (the
// triangle's bounding box, tested by the caller's loop bounds and again here), the triangle's
// normal, and the 9 cross products of the box's edges with the triangle's edges. Touching counts
// as overlap (<=), so the voxelisation is conservative: every cell the surface passes through is
// marked.
bool voxel_triangle_overlaps(vec3 a, vec3 b, vec3 c, vec3 centre, vec3 h) {
    a -= centre;
    b -= centre;
    c -= centre;
    if (any(greaterThan(min(a, min(b, c)), h)) || any(lessThan(max(a, max(b, c)), -h))) return false;
    vec3 e[3] = vec3[](b - a, c - b, a - c);
    vec3 n = cross(e[0], e[1]);
    if (abs(dot(n, a)) > dot(abs(n), h)) return false;  // the plane misses the box
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            vec3 axis = vec3(0.0);
            axis[(i + 1) % 3] = -e[j][(i + 2) % 3];  // unit_i x e_j
            axis[(i + 2) % 3] = e[j][(i + 1) % 3];
            float pa = dot(axis, a), pb = dot(axis, b), pc = dot(axis, c);
            float r = dot(abs(axis), h);
            if (min(pa, min(pb, pc)) > r || max(pa, max(pb, pc)) < -r) return false;
        }
    return true;
}

#endif
