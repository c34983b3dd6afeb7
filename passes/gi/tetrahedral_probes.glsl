// Light probes interpolated over tetrahedra (002_644d46bdce7e5305.txt L2809-2823): probe positions
// tessellated into tetrahedra, an SH per probe, the four SHs of the tetrahedron containing a point
// blended with its barycentric coordinates.
//
// The probes are a fixed TP_N^3 lattice over [-TP_EXTENT, TP_EXTENT]^3 in the Cornell box, probe
// index i + TP_N (j + TP_N k). The seed tessellates arbitrary probe positions with Delaunay-Watson
// (L2811); for a lattice every cube cell splits into the 6 tetrahedra of the Kuhn (Freudenthal)
// subdivision, one per order of the three axes along the cell's main diagonal: a Delaunay
// tetrahedralisation of the lattice (its points are cospherical per cell, so Delaunay is not
// unique; this split is one of the valid ones, and it matches across cell faces). The tetrahedra
// are built on the GPU (the preset's build.comp) into the buffer `tets`: 4 probe indices each, and
// the inverse of its edge matrix (tetrahedral_barycentric) so a lookup costs one matrix-vector
// product. The seed's GPU lookup is "a 3D brick map index volume" (L2817): here the lattice cell is
// the brick, cell c holds tetrahedra 6c .. 6c + 5, and within it the Kuhn simplex of permutation
// (a, b, c) holds the points whose in-cell coordinates satisfy f_a >= f_b >= f_c, so sorting the
// three fractions names the tetrahedron; its barycentric coordinates then come from its own
// matrix, and the tests check they are >= 0, i.e. that the tetrahedron found contains the point.
#ifndef PASSLAB_GI_TETRAHEDRAL_PROBES_GLSL
#define PASSLAB_GI_TETRAHEDRAL_PROBES_GLSL

#define TP_N 5
const int TP_PROBES = TP_N * TP_N * TP_N;
const int TP_CELLS = (TP_N - 1) * (TP_N - 1) * (TP_N - 1);
const int TP_TETS = 6 * TP_CELLS;
const float TP_EXTENT = 0.9;
const int TP_SH = 9;  // three bands (L2813: "3rd spherical harmonics coefficients")
const int TP_SURFACES = 18;  // the flat surfaces of gi/radiosity_patches.glsl (the table path)

vec3 tetrahedral_probe_position(int i) {
    ivec3 c = ivec3(i % TP_N, (i / TP_N) % TP_N, i / (TP_N * TP_N));
    return -TP_EXTENT + vec3(c) * (2.0 * TP_EXTENT / float(TP_N - 1));
}

int tetrahedral_probe_index(ivec3 c) { return c.x + TP_N * (c.y + TP_N * c.z); }

// Barycentric coordinates of x in the tetrahedron (v0, v1, v2, v3): solve
// [v0 - v3, v1 - v3, v2 - v3] (l0, l1, l2) = x - v3, and l3 = 1 - l0 - l1 - l2.
vec4 tetrahedral_barycentric(vec3 x, vec3 v0, vec3 v1, vec3 v2, vec3 v3) {
    vec3 l = inverse(mat3(v0 - v3, v1 - v3, v2 - v3)) * (x - v3);
    return vec4(l, 1.0 - l.x - l.y - l.z);
}

#endif

// The 6 axis orders of the Kuhn simplices; simplex k of a cell steps along TP_PERM[k].x, .y, .z.
const ivec3 TP_PERM[6] = ivec3[](ivec3(0, 1, 2), ivec3(0, 2, 1), ivec3(1, 0, 2), ivec3(1, 2, 0), ivec3(2, 0, 1), ivec3(2, 1, 0));

#ifdef TP_LOOKUP
// The tetrahedra: record 5t = probe indices, 5t + 1 .. 5t + 3 = the columns of the inverse edge
// matrix, 5t + 4 = v3 (build.comp); and the probes' SH (TP_SH rgb coefficients each).
layout(std430) readonly buffer Tets { ivec4 rec[]; } tets;
layout(std430) readonly buffer Probes { vec4 coeff[]; } probes;

// The tetrahedron containing x (clamped into the lattice) and x's barycentric coordinates in it.
void tetrahedral_locate(vec3 x, out int tet, out vec4 weights) {
    x = clamp(x, vec3(-TP_EXTENT), vec3(TP_EXTENT));
    vec3 g = (x + TP_EXTENT) / (2.0 * TP_EXTENT) * float(TP_N - 1);
    ivec3 c = clamp(ivec3(floor(g)), ivec3(0), ivec3(TP_N - 2));
    vec3 f = g - vec3(c);
    // the permutation sorting f descending: f_a >= f_b >= f_c
    int k = f.x >= f.y ? (f.y >= f.z ? 0 : (f.x >= f.z ? 1 : 4)) : (f.x >= f.z ? 2 : (f.y >= f.z ? 3 : 5));
    tet = 6 * (c.x + (TP_N - 1) * (c.y + (TP_N - 1) * c.z)) + k;
    mat3 inv = mat3(intBitsToFloat(tets.rec[5 * tet + 1].xyz), intBitsToFloat(tets.rec[5 * tet + 2].xyz), intBitsToFloat(tets.rec[5 * tet + 3].xyz));
    vec3 l = inv * (x - intBitsToFloat(tets.rec[5 * tet + 4].xyz));
    weights = vec4(l, 1.0 - l.x - l.y - l.z);
}

#ifdef TP_TABLE
// The probes' irradiance per surface normal (the preset's table.comp): E of probe k for surface s
// at k * TP_SURFACES + s.
layout(std430) readonly buffer Table { vec4 e[]; } table;

// The irradiance of surface s blended from the tetrahedron's four probes v with weights w.
vec3 tetrahedral_blend_table(ivec4 v, vec4 w, int s) {
    return w.x * table.e[v.x * TP_SURFACES + s].rgb + w.y * table.e[v.y * TP_SURFACES + s].rgb +
           w.z * table.e[v.z * TP_SURFACES + s].rgb + w.w * table.e[v.w * TP_SURFACES + s].rgb;
}
#endif

// SH coefficient i blended from the tetrahedron's four probes v with weights w (L2814).
vec3 tetrahedral_blend(ivec4 v, vec4 w, int i) {
    return w.x * probes.coeff[v.x * TP_SH + i].rgb + w.y * probes.coeff[v.y * TP_SH + i].rgb +
           w.z * probes.coeff[v.z * TP_SH + i].rgb + w.w * probes.coeff[v.w * TP_SH + i].rgb;
}

// The same at x's tetrahedron, with the weights clamped to >= 0 and renormalised (inside the
// tetrahedron they are >= -1e-7: rounding).
vec3 tetrahedral_coeff(int tet, vec4 weights, int i) {
    vec4 w = max(weights, 0.0);
    return tetrahedral_blend(tets.rec[5 * tet], w / (w.x + w.y + w.z + w.w), i);
}
#endif
