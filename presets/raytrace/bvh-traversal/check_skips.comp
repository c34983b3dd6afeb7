#version 450
// bvh-traversal's buffer check of the skip lists the walk follows (one thread per node of the
// scene buffer): skipToNode(i) = i + subtreeSize(i) (002_644d46bdce7e5305.txt L1912-1914: the
// tree in depth-first preorder, a missed node continues at its skip). Checked through local
// conditions on every node i of a mesh whose nodes are [first, end):
//   1  i < skip(i) <= end, and the root's skip(first) = end        (the list covers the mesh)
//   2  a leaf: skip(i) = i + 1                                     (a leaf's subtree is itself)
//   4  an inner node: left child l = i + 1, right child r = skip(l), with i < l < r < skip(i) and
//      skip(r) = skip(i)                                           (both subtrees, nothing else)
//   8  the children's boxes inside the node's box, a leaf's triangles inside its box
// Induction from the leaves: with 2 and 4 on every node, skip(i) - i = 1 + (skip(l) - l) +
// (skip(r) - r) = 1 + subtreeSize(l) + subtreeSize(r) = subtreeSize(i). report[i] = (error bits,
// leaf triangle count); the tests sum both over the buffer: no error, every triangle in one leaf.
layout(local_size_x = 64) in;
#include "raytrace/bvh.glsl"
layout(std430) writeonly buffer Report { uvec2 report[]; } node_report;

bool inside(vec3 lo, vec3 hi, vec3 plo, vec3 phi) { return all(greaterThanEqual(lo, plo)) && all(lessThanEqual(hi, phi)); }

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= scene.header.node_count || i >= uint(node_report.report.length())) return;
    PlSceneMesh m = pl_scene_mesh(0u);
    for (uint k = 1u; k < scene.header.mesh_count; ++k) {
        PlSceneMesh c = pl_scene_mesh(k);
        if (i >= c.node_offset && i < c.node_offset + c.node_count) m = c;
    }
    uint end = m.node_offset + m.node_count, errors = 0u;
    PlBvhNode n = pl_bvh_node(i);
    uint skip = n.skip;
    if (skip <= i || skip > end || (i == m.node_offset && skip != end)) errors |= 1u;
    uint count = pl_bvh_leaf_count(n);
    if (count > 0u) {
        if (skip != i + 1u) errors |= 2u;
        for (uint j = pl_bvh_leaf_first(n); j < pl_bvh_leaf_first(n) + count; ++j) {
            PlSceneTriangle t = pl_scene_triangle(j);
            vec3 lo = min(t.v0, min(t.v1, t.v2)), hi = max(t.v0, max(t.v1, t.v2));
            if (!inside(lo, hi, n.lo, n.hi)) errors |= 8u;
        }
    } else if ((errors & 1u) == 0u) {
        uint l = i + 1u;
        PlBvhNode left = pl_bvh_node(l);
        uint r = left.skip;
        if (!(l < r && r < skip)) errors |= 4u;
        else {
            PlBvhNode right = pl_bvh_node(r);
            if (right.skip != skip) errors |= 4u;
            if (!inside(left.lo, left.hi, n.lo, n.hi) || !inside(right.lo, right.hi, n.lo, n.hi)) errors |= 8u;
        }
    }
    node_report.report[i] = uvec2(errors, count);
}
