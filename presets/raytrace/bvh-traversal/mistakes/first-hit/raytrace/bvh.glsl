// MISTAKE first-hit: the exercise solved, but the walk stops at the first leaf with a hit.
// EXERCISE — this file shadows passes/raytrace/bvh.glsl for raytrace/bvh-traversal.
//     passlab run   presets/raytrace/bvh-traversal --exercise presets/raytrace/bvh-traversal/exercise
//     passlab grade presets/raytrace/bvh-traversal --exercise presets/raytrace/bvh-traversal/exercise
// Two TODOs: the slab test (pl_ray_aabb) and the skip-list walk (pl_bvh_closest). As shipped no
// box is hit and the walk ends at once: every ray misses. (A walk that visits every node is right
// but as slow as brute force: ~4 s per frame here, near the 20 s watchdog under load.)
// Ray queries against a host-built scene buffer ([buffers] generator = "bvh" | "triangles",
// docs/format.md). The structs PlSceneHeader, PlSceneMesh, PlBvhNode and PlSceneTriangle come
// with every shader's preamble, generated from their one C++ definition (host/scene/scene_gpu.hpp);
// this file declares the buffer and the queries.
//
// The buffer is `scene` here; a graph buffer of another name binds with bind = { scene = "NAME" }.
//
// Instances (002_644d46bdce7e5305.txt L1906-1910: static per-object BVHs under a dynamic top
// level; here the top level is the caller's loop over its instances): each mesh's BVH is in
// object space and the caller passes `object_from_world`, the inverse of the instance's
// placement. The direction is transformed but NOT renormalised (the seed renormalises at
// L2113, which changes t on a scaled instance), so every hit's t is the world ray's parameter
// and hits of different instances compare directly.
//
// Exactness: the closest hit is the smallest (t, instance, prim), so it does not depend on the
// order triangles are visited in, and the arithmetic that produces t is `precise` (no fused
// multiply-adds chosen differently per shader): a BVH query, the brute-force reference and an
// occlusion query in three different shaders agree bit for bit.
#ifndef PASSLAB_RAYTRACE_BVH_GLSL
#define PASSLAB_RAYTRACE_BVH_GLSL

layout(std430) readonly buffer PlScene {
    PlSceneHeader header;
    uvec4 records[];  // mesh table, nodes, triangles: see host/scene/scene_gpu.hpp
} scene;

PlSceneMesh pl_scene_mesh(uint m) {
    uvec4 r = scene.records[scene.header.meshes_at + m * PL_SCENE_MESH_RECORDS];
    return PlSceneMesh(r.x, r.y, r.z, r.w);
}

PlBvhNode pl_bvh_node(uint i) {
    uint k = scene.header.nodes_at + i * PL_BVH_NODE_RECORDS;
    uvec4 a = scene.records[k], b = scene.records[k + 1u];
    return PlBvhNode(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w);
}

PlSceneTriangle pl_scene_triangle(uint j) {
    uint k = scene.header.triangles_at + j * PL_SCENE_TRIANGLE_RECORDS;
    uvec4 a = scene.records[k], b = scene.records[k + 1u], c = scene.records[k + 2u];
    return PlSceneTriangle(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w, uintBitsToFloat(c.xyz), c.w);
}

// A leaf's triangles: first .. first + count - 1; leaf == 0 marks an inner node.
uint pl_bvh_leaf_first(PlBvhNode n) { return n.leaf >> PL_BVH_LEAF_COUNT_BITS; }
uint pl_bvh_leaf_count(PlBvhNode n) { return n.leaf & ((1u << PL_BVH_LEAF_COUNT_BITS) - 1u); }

struct PlHit {
    float t;       // ray parameter of the closest hit so far; the query's tmax while none
    int instance;  // the caller's instance id; -1 = no hit
    uint mesh;     // index in the buffer's `meshes`
    uint prim;     // triangle in that mesh's index list (indices[3 * prim ..])
    vec2 bary;     // (u, v): the hit is (1 - u - v) v0 + u v1 + v v2
    uint nodes;    // cost counters, accumulated over queries: nodes visited ...
    uint tests;    // ... and ray-triangle tests
};

PlHit pl_no_hit(float tmax) { return PlHit(tmax, -1, 0u, 0u, vec2(0.0), 0u, 0u); }

// Whether a hit at (t, instance, prim) is closer than `best`: smaller t, ties to the smaller
// instance, then prim, so the answer does not depend on the visiting order.
bool pl_closer(float t, int instance, uint prim, PlHit best) {
    if (t != best.t) return t < best.t;
    return best.instance >= 0 && (instance < best.instance || (instance == best.instance && prim < best.prim));
}

// Moller & Trumbore 1997, "Fast, minimum storage ray-triangle intersection" (JGT 2(1)):
// solves o + t d = (1 - u - v) v0 + u v1 + v v2 by Cramer's rule with two cross products and
// one division. Two-sided (shadow and inside rays hit back faces). The seed's test
// (002_644d46bdce7e5305.txt L2040-2088) intersects the plane first and then solves for the
// parametric coordinates with 1e-5 edge slack; Moller-Trumbore needs no plane, no slack and no
// normalised direction. det == 0 (ray parallel to the plane, or a zero-area triangle with a
// repeated corner) is a miss; no scale-dependent epsilon.
bool pl_ray_triangle(vec3 o, vec3 d, vec3 v0, vec3 v1, vec3 v2, out float t, out vec2 bary) {
    precise vec3 e1 = v1 - v0, e2 = v2 - v0;
    precise vec3 p = cross(d, e2);
    precise float det = dot(e1, p);
    t = 0.0;
    bary = vec2(0.0);
    if (det == 0.0) return false;
    precise float inv_det = 1.0 / det;
    precise vec3 s = o - v0;
    precise float u = dot(s, p) * inv_det;
    if (u < 0.0 || u > 1.0) return false;
    precise vec3 q = cross(s, e1);
    precise float v = dot(d, q) * inv_det;
    if (v < 0.0 || u + v > 1.0) return false;
    precise float along = dot(e2, q) * inv_det;
    t = along;
    bary = vec2(u, v);
    return true;
}

// 1 / d per component, with zero components replaced by a tiny value of their sign: the slab
// test then never forms 0 * inf = NaN when the origin lies on a slab plane.
vec3 pl_inverse_direction(vec3 d) {
    vec3 safe = mix(d, mix(vec3(-1e-30), vec3(1e-30), greaterThanEqual(d, vec3(0.0))), lessThan(abs(d), vec3(1e-30)));
    return 1.0 / safe;
}

// Ray-box slab test, the seed's bvhAABBIntersect (002_644d46bdce7e5305.txt L1996-2015)
// restricted to [tmin, tmax]. The box's far distance is enlarged by 2 gamma(3) = 3.6e-7
// relative (Pharr, Jakob, Humphreys, PBRT 3rd ed., 3.9.2 "robust ray-bounds intersections"),
// so rounding never rejects a box around a triangle the triangle test hits. Inclusive at
// tmax: a box touching the current closest t may still hold an equal-t hit that wins the tie.
bool pl_ray_aabb(vec3 lo, vec3 hi, vec3 o, vec3 inv_d, float tmin, float tmax) {
    // TODO 1: the slab test (002_644d46bdce7e5305.txt L1996-2015, bvhAABBIntersect). Per axis the
    // ray o + t d crosses the slab lo..hi at t0 = (lo - o) / d and t1 = (hi - o) / d (inv_d = 1/d);
    // near = min(t0, t1), far = max(t0, t1) (a negative d swaps them). The box is hit on
    // [tn, tf] with tn = max(near.x, near.y, near.z, tmin) and tf = min(far.x, far.y, far.z)
    // (enlarge tf by (1 + 3.6e-7): PBRT 3.9.2, rounding must never reject a box the triangle
    // test would hit); the box counts when tn <= min(tf, tmax). As shipped: no box is hit.
    vec3 t0 = (lo - o) * inv_d, t1 = (hi - o) * inv_d;
    vec3 near = min(t0, t1), far = max(t0, t1);
    float tn = max(max(near.x, near.y), max(near.z, tmin));
    float tf = min(min(far.x, far.y), far.z) * (1.0 + 3.6e-7);
    return tn <= min(tf, tmax);
}

// The world ray in an instance's object space (direction not renormalised, see the top).
void pl_to_object(mat4 object_from_world, vec3 ro, vec3 rd, out vec3 o, out vec3 d) {
    precise vec4 oo = object_from_world * vec4(ro, 1.0);
    precise vec3 dd = mat3(object_from_world) * rd;
    o = oo.xyz;
    d = dd;
}

// Tests triangle j of the buffer and keeps it in `hit` if it is closer and beyond tmin.
void pl_test_triangle(uint j, vec3 o, vec3 d, float tmin, int instance, inout PlHit hit) {
    PlSceneTriangle tri = pl_scene_triangle(j);
    float t;
    vec2 bary;
    hit.tests++;
    if (pl_ray_triangle(o, d, tri.v0, tri.v1, tri.v2, t, bary) && t > tmin && pl_closer(t, instance, tri.prim, hit)) {
        hit.t = t;
        hit.instance = instance;
        hit.mesh = tri.mesh;
        hit.prim = tri.prim;
        hit.bary = bary;
    }
}

void pl_test_triangles(uint first, uint count, vec3 o, vec3 d, float tmin, int instance, inout PlHit hit) {
    for (uint j = first; j < first + count; ++j) pl_test_triangle(j, o, d, tmin, instance, hit);
}

// Closest hit on one instance of `mesh` through its BVH: the stackless skip-list walk of the
// seed (002_644d46bdce7e5305.txt L2104-2129): a box that is hit continues at the next node
// (its first child, or the node after a leaf), a box that is missed jumps to its skip index,
// past its whole subtree. The closest t so far shrinks the ray, so far boxes are skipped too.
void pl_bvh_closest(uint mesh, mat4 object_from_world, int instance, vec3 ro, vec3 rd, float tmin, inout PlHit hit) {
    vec3 o, d;
    pl_to_object(object_from_world, ro, rd, o, d);
    vec3 inv_d = pl_inverse_direction(d);
    PlSceneMesh m = pl_scene_mesh(mesh);
    // A generator = "triangles" buffer has no nodes: test every triangle (right, only slower).
    if (m.node_count == 0u) {
        pl_test_triangles(m.triangle_offset, m.triangle_count, o, d, tmin, instance, hit);
        return;
    }
    uint i = m.node_offset, end = m.node_offset + m.node_count;
    while (i < end) {
        PlBvhNode n = pl_bvh_node(i);
        hit.nodes++;
        // TODO 2: the skip-list walk (002_644d46bdce7e5305.txt L2104-2129). Test the node's box
        // against the ray shortened to the closest hit so far (tmax = hit.t: farther boxes cannot
        // hold a closer hit). Missed: continue at n.skip, past the node's whole subtree
        // ("Skip this static BVH node and all its children", L2121-2124). Hit: test the node's
        // triangles (pl_test_triangles over pl_bvh_leaf_first(n), pl_bvh_leaf_count(n); an inner
        // node has none) and continue at i + 1 -- whether or not a triangle was hit: the first
        // hit found is not necessarily the closest. As shipped the walk ends at once.
        if (!pl_ray_aabb(n.lo, n.hi, o, inv_d, tmin, hit.t)) {
            i = n.skip;
            continue;
        }
        pl_test_triangles(pl_bvh_leaf_first(n), pl_bvh_leaf_count(n), o, d, tmin, instance, hit);
        if (hit.instance == instance) return;   // found it: stop at the first hit
        ++i;
    }
}

// Any hit with tmin < t < tmax on one instance (shadow and visibility rays): the seed's
// bvhRayShootForVisibilityCheck (002_644d46bdce7e5305.txt L2092-2136), returning at the first
// triangle found instead of looking for the closest.
bool pl_any_triangle(uint first, uint count, vec3 o, vec3 d, float tmin, float tmax) {
    for (uint j = first; j < first + count; ++j) {
        PlSceneTriangle tri = pl_scene_triangle(j);
        float t;
        vec2 bary;
        if (pl_ray_triangle(o, d, tri.v0, tri.v1, tri.v2, t, bary) && t > tmin && t < tmax) return true;
    }
    return false;
}

bool pl_bvh_occluded(uint mesh, mat4 object_from_world, vec3 ro, vec3 rd, float tmin, float tmax) {
    vec3 o, d;
    pl_to_object(object_from_world, ro, rd, o, d);
    vec3 inv_d = pl_inverse_direction(d);
    PlSceneMesh m = pl_scene_mesh(mesh);
    if (m.node_count == 0u) return pl_any_triangle(m.triangle_offset, m.triangle_count, o, d, tmin, tmax);
    uint i = m.node_offset, end = m.node_offset + m.node_count;
    while (i < end) {
        PlBvhNode n = pl_bvh_node(i);
        if (!pl_ray_aabb(n.lo, n.hi, o, inv_d, tmin, tmax)) {
            i = n.skip;
            continue;
        }
        if (pl_any_triangle(pl_bvh_leaf_first(n), pl_bvh_leaf_count(n), o, d, tmin, tmax)) return true;
        ++i;
    }
    return false;
}

// The reference: every triangle of one instance of `mesh`, no nodes. Works on both generators'
// buffers (the triangle records and the mesh table are the same).
void pl_brute_closest(uint mesh, mat4 object_from_world, int instance, vec3 ro, vec3 rd, float tmin, inout PlHit hit) {
    vec3 o, d;
    pl_to_object(object_from_world, ro, rd, o, d);
    PlSceneMesh m = pl_scene_mesh(mesh);
    pl_test_triangles(m.triangle_offset, m.triangle_count, o, d, tmin, instance, hit);
}

#endif
