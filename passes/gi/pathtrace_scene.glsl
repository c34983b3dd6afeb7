// Ray queries against the GI family's scenes for the path tracer (passes/gi/pathtrace.glsl):
// the Cornell box of passes/gi/cornell.glsl, or the white-furnace sphere. Built on the host BVH
// and the one traversal library (raytrace/bvh.glsl); the graph's scene buffer lists its meshes
// in the order
//
//   [buffers]
//   scene = { generator = "bvh", meshes = ["wall", "block", "ball"] }   # mesh 0, 1, 2
//
// ("ball", the furnace sphere, may be left out by a graph that only traces the Cornell box).
// The ray is tested against every instance with its inverse placement (the top level is this
// loop, 002_644d46bdce7e5305.txt L1906-1910); the inverses are computed once per invocation by
// pathtrace_scene_init.
#ifndef PASSLAB_GI_PATHTRACE_SCENE_GLSL
#define PASSLAB_GI_PATHTRACE_SCENE_GLSL

#include "raytrace/bvh.glsl"
#include "gi/cornell.glsl"

const int PATHTRACE_CORNELL = 0;  // the comparison scene; the environment is black
const int PATHTRACE_FURNACE = 1;  // one albedo-1 sphere (radius 1 at the origin, turned) in a radiance-1 environment
const uint PATHTRACE_MESH_WALL = 0u, PATHTRACE_MESH_BLOCK = 1u, PATHTRACE_MESH_BALL = 2u;
const int PATHTRACE_MAX_INSTANCES = CORNELL_WALLS + CORNELL_BLOCKS;

// Where a new ray starts off a surface, along the normal on the side it leaves (world units;
// the box is 2 wide, float32 hit points are good to ~1e-7).
const float PATHTRACE_OFFSET = 1e-4;

struct PathtraceHit {
    bool hit;
    vec3 p;       // world position
    vec3 n;       // unit geometric normal, facing the incoming ray
    vec3 albedo;  // diffuse reflectance rho
};

int pathtrace_scene_id;
int pathtrace_instances;
uint pathtrace_mesh[PATHTRACE_MAX_INSTANCES];
mat4 pathtrace_world_from_object[PATHTRACE_MAX_INSTANCES];
mat4 pathtrace_object_from_world[PATHTRACE_MAX_INSTANCES];

void pathtrace_scene_init(int scene_id) {
    pathtrace_scene_id = scene_id;
    if (scene_id == PATHTRACE_FURNACE) {
        pathtrace_instances = 1;
        pathtrace_mesh[0] = PATHTRACE_MESH_BALL;
        // Turned off the axes: with the view camera at pitch 0, the eye rays of the middle row
        // lie exactly in the sphere's equator plane, where float Moller-Trumbore can slip
        // through the edge shared by two facets (seen: 2 of 1296 pixels black, the ray entering
        // and its paths trapped inside).
        pathtrace_world_from_object[0] = cornell_rot_x(0.5) * cornell_rot_z(0.3);
    } else {
        pathtrace_instances = CORNELL_WALLS + CORNELL_BLOCKS;
        for (int i = 0; i < CORNELL_WALLS; ++i) {
            pathtrace_mesh[i] = PATHTRACE_MESH_WALL;
            pathtrace_world_from_object[i] = cornell_wall(i);
        }
        for (int i = 0; i < CORNELL_BLOCKS; ++i) {
            pathtrace_mesh[CORNELL_WALLS + i] = PATHTRACE_MESH_BLOCK;
            pathtrace_world_from_object[CORNELL_WALLS + i] = cornell_block(i);
        }
    }
    for (int i = 0; i < pathtrace_instances; ++i) pathtrace_object_from_world[i] = inverse(pathtrace_world_from_object[i]);
}

// The radiance arriving from the environment (rays that leave the scene): 0 around the Cornell
// box (its open side looks into the dark), 1 in the furnace.
vec3 pathtrace_environment() { return pathtrace_scene_id == PATHTRACE_FURNACE ? vec3(1.0) : vec3(0.0); }

// The record of triangle `prim` of `mesh` (PlHit gives the triangle's index in its mesh, not its
// record): the BVH walked down the boxes containing the object-space hit point `p`, a few nodes
// per level. The box test is widened by `slack` (the point is computed, not exact).
PlSceneTriangle pathtrace_triangle(uint mesh, uint prim, vec3 p, float slack) {
    PlSceneMesh m = pl_scene_mesh(mesh);
    PlSceneTriangle tri = pl_scene_triangle(m.triangle_offset);
    if (m.node_count == 0u) {  // generator = "triangles": every record of the mesh
        for (uint j = m.triangle_offset; j < m.triangle_offset + m.triangle_count; ++j) {
            tri = pl_scene_triangle(j);
            if (tri.prim == prim) return tri;
        }
        return tri;
    }
    uint i = m.node_offset, end = m.node_offset + m.node_count;
    while (i < end) {
        PlBvhNode n = pl_bvh_node(i);
        if (any(lessThan(p, n.lo - slack)) || any(greaterThan(p, n.hi + slack))) {
            i = n.skip;
            continue;
        }
        uint first = pl_bvh_leaf_first(n);
        for (uint j = first; j < first + pl_bvh_leaf_count(n); ++j) {
            tri = pl_scene_triangle(j);
            if (tri.prim == prim) return tri;
        }
        ++i;
    }
    return tri;
}

// The object-space geometric normal of the hit (either orientation). The plane and the cube have
// theirs in closed form (the cube's face is the hit point's largest coordinate), which spares
// the triangle lookup on the Cornell box; the sphere's facets come from their corners.
vec3 pathtrace_object_normal(PlHit h, vec3 p_object) {
    if (h.mesh == PATHTRACE_MESH_WALL) return vec3(0.0, 1.0, 0.0);
    if (h.mesh == PATHTRACE_MESH_BLOCK) {
        vec3 a = abs(p_object);
        return a.x >= a.y && a.x >= a.z ? vec3(1.0, 0.0, 0.0) : (a.y >= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    }
    PlSceneTriangle tri = pathtrace_triangle(h.mesh, h.prim, p_object, 1e-4);
    return cross(tri.v1 - tri.v0, tri.v2 - tri.v0);
}

vec3 pathtrace_albedo(uint mesh, int instance) {
    if (pathtrace_scene_id == PATHTRACE_FURNACE) return vec3(1.0);
    return cornell_albedo(int(mesh), mesh == PATHTRACE_MESH_WALL ? instance : instance - CORNELL_WALLS);
}

// The closest surface along ro + t rd, t > 0 (rd need not be unit length).
PathtraceHit pathtrace_closest(vec3 ro, vec3 rd) {
    PlHit h = pl_no_hit(1e30);
    for (int i = 0; i < pathtrace_instances; ++i)
        pl_bvh_closest(pathtrace_mesh[i], pathtrace_object_from_world[i], i, ro, rd, 0.0, h);
    if (h.instance < 0) return PathtraceHit(false, vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0));
    int i = h.instance;
    vec3 p = ro + h.t * rd;
    vec3 p_object = (pathtrace_object_from_world[i] * vec4(p, 1.0)).xyz;
    // Normals transform with the inverse transpose of the placement.
    vec3 n = normalize(transpose(mat3(pathtrace_object_from_world[i])) * pathtrace_object_normal(h, p_object));
    n = dot(n, rd) > 0.0 ? -n : n;
    return PathtraceHit(true, p, n, pathtrace_albedo(h.mesh, i));
}

// Whether anything lies on the segment ro .. ro + rd, ends excluded (shadow rays).
bool pathtrace_occluded(vec3 ro, vec3 rd) {
    for (int i = 0; i < pathtrace_instances; ++i)
        if (pl_bvh_occluded(pathtrace_mesh[i], pathtrace_object_from_world[i], ro, rd, 0.0, 1.0 - 1e-4)) return true;
    return false;
}

#endif
