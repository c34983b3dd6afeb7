// The radiosity preset's finite elements: the Cornell box of gi/cornell.glsl cut into patches
// (000_c9f7e5de708ecbb3.txt L5068-5071: "discretize scene into patches, assume everything is
// perfectly diffuse"), and the map from a ray hit to the patch it landed on.
//
// Surfaces: walls 0..4 of cornell.glsl, wall 5 the front wall that closes the box (only in the
// closed-box test: the open box lets rays escape towards the camera), then the faces of the two
// blocks, face slot by face slot (+X, -X, +Y, +Z, -Z, -Y; both blocks per slot), so the two
// bottom faces, which rest on the floor (no hemisphere to gather from, never seen), are the last
// 2 * RAD_FACE_N^2 patches. A wall is RAD_WALL_N x RAD_WALL_N patches, a block face RAD_FACE_N^2.
// Patch index = surface's first patch + row * n + column, row/column along the surface's own
// (s, t) axes: walls the plane mesh's object x and z, block faces the two cube axes other than
// the face's normal axis.
#ifndef PASSLAB_GI_RADIOSITY_PATCHES_GLSL
#define PASSLAB_GI_RADIOSITY_PATCHES_GLSL

#include "gi/cornell.glsl"

#ifndef RAD_WALL_N
#define RAD_WALL_N 16
#endif
#ifndef RAD_FACE_N
#define RAD_FACE_N 4
#endif

#ifndef RAD_RAYS
#define RAD_RAYS 256  // form-factor rays per patch, a 16 x 16 stratified grid (a square)
#endif
const int RAD_MAX_ITERATIONS = 32;  // rows of the buffer `radiance`: L0 and up to 31 iterates

const int RAD_WALLS = 6;  // cornell's five and the front wall
const int RAD_WALL_PATCHES = RAD_WALL_N * RAD_WALL_N;
const int RAD_FACE_PATCHES = RAD_FACE_N * RAD_FACE_N;
const int RAD_PATCHES = RAD_WALLS * RAD_WALL_PATCHES + CORNELL_BLOCKS * 6 * RAD_FACE_PATCHES;

// world_from_object of wall i: cornell's walls, and the front wall (+Y turned to -Z).
mat4 radiosity_wall(int i) {
    if (i < CORNELL_WALLS) return cornell_wall(i);
    return cornell_translate(vec3(0, 0, 1)) * cornell_rot_x(-1.5707963);
}

// A patch's surface: which mesh instance, its placement and its own axes in object space.
struct RadSurface {
    int mesh;       // 0 wall (plane mesh), 1 block (cube mesh)
    int instance;   // wall 0..5 or block 0..1
    int n;          // patches per side
    int first;      // index of its patch (0, 0)
    vec3 normal;    // object-space normal
    vec3 s_axis;    // object-space axis of columns
    vec3 t_axis;    // ... and of rows
    float half_size;  // the surface spans [-half_size, half_size] along s and t (plane 1, cube 0.5)
};

// Cube face slot f = 0..5: +X, -X, +Y, +Z, -Z, -Y (the bottom last).
vec3 radiosity_face_normal(int f) {
    const vec3 n[6] = vec3[](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(0, 0, -1), vec3(0, -1, 0));
    return n[f];
}
const int RAD_FACE_BOTTOM = 5;
const int RAD_LIVE_PATCHES = RAD_PATCHES - CORNELL_BLOCKS * RAD_FACE_PATCHES;  // all but the bottoms

RadSurface radiosity_surface(int surface) {
    if (surface < RAD_WALLS)
        return RadSurface(0, surface, RAD_WALL_N, surface * RAD_WALL_PATCHES, vec3(0, 1, 0), vec3(1, 0, 0), vec3(0, 0, 1), 1.0);
    int k = surface - RAD_WALLS, f = k / CORNELL_BLOCKS;
    vec3 n = radiosity_face_normal(f), a = abs(n);
    vec3 s = a.x > 0.5 ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 t = a.z > 0.5 ? vec3(0, 1, 0) : vec3(0, 0, 1);
    return RadSurface(1, k % CORNELL_BLOCKS, RAD_FACE_N, RAD_WALLS * RAD_WALL_PATCHES + k * RAD_FACE_PATCHES, n, s, t, 0.5);
}

int radiosity_surface_of_patch(int p) {
    if (p < RAD_WALLS * RAD_WALL_PATCHES) return p / RAD_WALL_PATCHES;
    return RAD_WALLS + (p - RAD_WALLS * RAD_WALL_PATCHES) / RAD_FACE_PATCHES;
}

mat4 radiosity_world_from_object(RadSurface s) {
    return s.mesh == 0 ? radiosity_wall(s.instance) : cornell_block(s.instance);
}

// Object-space point of surface coordinates (a, b) in [0, 1]^2.
vec3 radiosity_object_point(RadSurface s, vec2 ab) {
    // the plane mesh lies in its y = 0 plane; a cube face at distance 0.5 along its normal
    return s.normal * (s.mesh == 0 ? 0.0 : 0.5) + (2.0 * ab.x - 1.0) * s.half_size * s.s_axis + (2.0 * ab.y - 1.0) * s.half_size * s.t_axis;
}

// Surface coordinates in [0, 1]^2 of an object-space point on the surface.
vec2 radiosity_surface_coords(RadSurface s, vec3 o) {
    return clamp(vec2(dot(o, s.s_axis), dot(o, s.t_axis)) / (2.0 * s.half_size) + 0.5, 0.0, 1.0);
}

int radiosity_patch_at(RadSurface s, vec2 ab) {
    ivec2 c = min(ivec2(ab * float(s.n)), ivec2(s.n - 1));
    return s.first + c.y * s.n + c.x;
}

// The surface of a hit on `mesh`/`instance` at object-space point o: walls are one surface each;
// on a cube the face is the axis of the largest coordinate (the point lies on |o_axis| = 0.5).
int radiosity_surface_of_hit(int mesh, int instance, vec3 o) {
    if (mesh == 0) return instance;
    vec3 a = abs(o);
    int f = (a.x >= a.y && a.x >= a.z) ? (o.x > 0.0 ? 0 : 1) : (a.y >= a.z ? (o.y > 0.0 ? 2 : RAD_FACE_BOTTOM) : (o.z > 0.0 ? 3 : 4));
    return RAD_WALLS + f * CORNELL_BLOCKS + instance;
}

// World-space normal of a surface (inverse transpose: the blocks are scaled non-uniformly).
vec3 radiosity_world_normal(RadSurface s) {
    mat3 m = mat3(radiosity_world_from_object(s));
    return normalize(transpose(inverse(m)) * s.normal);
}

#endif
