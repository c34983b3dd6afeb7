// The GPU layout of the host-built scene buffers ([buffers] generator = "bvh" | "triangles"),
// defined once here for both sides as the frame block is (exec/frame_block.hpp): the C++ structs
// (std430: every member 4-byte scalars or vec3 + scalar pairs, so no hidden padding), static_asserts
// on their offsets and sizes, and the GLSL text that mirrors them member for member, which the
// preamble gives every shader. passes/raytrace/bvh.glsl reads the buffer with these structs.
//
// One buffer = PlSceneHeader, then an array of 16-byte records (uvec4 in GLSL, because std430
// allows one runtime array per block and the buffer holds three kinds of element):
//   records[meshes_at    + m]                        PlSceneMesh      (1 record)
//   records[nodes_at     + 2 * i .. + 1]             PlBvhNode        (2 records; bvh only)
//   records[triangles_at + 3 * j .. + 2]             PlSceneTriangle  (3 records)
// Per mesh (in the order of `meshes`), its nodes and its triangles are contiguous: the mesh's
// BVH is in its own object space (002_644d46bdce7e5305.txt L1908-1910: static per-object BVHs
// under a dynamic top level), so a shader places instances by transforming the ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace pl::scene::gpu {

struct SceneHeader {
    uint32_t mesh_count;
    uint32_t node_count;      // all meshes' nodes; 0 for generator = "triangles"
    uint32_t triangle_count;  // all meshes' triangles
    uint32_t leaf_size;       // the build's bound on triangles per leaf; 0 without nodes
    uint32_t meshes_at;       // record index of the mesh table
    uint32_t nodes_at;        // record index of node 0
    uint32_t triangles_at;    // record index of triangle 0
    uint32_t record_count;    // records after the header
};
static_assert(sizeof(SceneHeader) == 32);
static_assert(offsetof(SceneHeader, meshes_at) == 16);

// The seed's staticBVHSkipListObject (002_644d46bdce7e5305.txt L1946-1951). Node and triangle
// indices are global (over the whole buffer), so skip indices need no per-mesh rebasing.
struct SceneMesh {
    uint32_t node_offset;  // the mesh's root node
    uint32_t node_count;   // its nodes are node_offset .. node_offset + node_count - 1
    uint32_t triangle_offset;
    uint32_t triangle_count;
};
static_assert(sizeof(SceneMesh) == 16);

// The seed's staticBVHSkipListNode (L1939-1944) in 32 bytes: `leaf` packs the triangle range of
// a leaf, first triangle << 4 | count (count 1..15), and is 0 for an inner node, whose first
// child is the next node. Traversal: a hit goes to i + 1, a miss to skip = i + subtree size
// (a leaf's skip is i + 1 too).
inline constexpr uint32_t kLeafCountBits = 4;
struct BvhNode {
    float lo[3];
    uint32_t skip;
    float hi[3];
    uint32_t leaf;
};
static_assert(sizeof(BvhNode) == 32);
static_assert(offsetof(BvhNode, skip) == 12 && offsetof(BvhNode, hi) == 16 && offsetof(BvhNode, leaf) == 28);

// Object-space corner positions; `mesh` is the index in `meshes`, `prim` the triangle's index
// in that mesh's index list (indices[3 * prim ..]), so a shader can fetch its attributes.
struct SceneTriangle {
    float v0[3];
    uint32_t mesh;
    float v1[3];
    uint32_t prim;
    float v2[3];
    uint32_t pad_;
};
static_assert(sizeof(SceneTriangle) == 48);
static_assert(offsetof(SceneTriangle, v1) == 16 && offsetof(SceneTriangle, prim) == 28 && offsetof(SceneTriangle, v2) == 32);

inline constexpr size_t kRecordBytes = 16;
static_assert(sizeof(SceneMesh) % kRecordBytes == 0 && sizeof(BvhNode) % kRecordBytes == 0 &&
              sizeof(SceneTriangle) % kRecordBytes == 0 && sizeof(SceneHeader) % kRecordBytes == 0);

// Mirrors the structs above member for member (std430 gives the same offsets: vec3 at 16-byte
// alignment followed by a scalar fills 16 bytes). The record counts are generated from sizeof.
inline std::string scene_glsl() {
    auto records = [](size_t bytes) { return std::to_string(bytes / kRecordBytes) + "u"; };
    return "struct PlSceneHeader { uint mesh_count; uint node_count; uint triangle_count; uint leaf_size;"
           " uint meshes_at; uint nodes_at; uint triangles_at; uint record_count; };\n"
           "struct PlSceneMesh { uint node_offset; uint node_count; uint triangle_offset; uint triangle_count; };\n"
           "struct PlBvhNode { vec3 lo; uint skip; vec3 hi; uint leaf; };\n"
           "struct PlSceneTriangle { vec3 v0; uint mesh; vec3 v1; uint prim; vec3 v2; uint pad_; };\n"
           "const uint PL_SCENE_MESH_RECORDS = " + records(sizeof(SceneMesh)) + ";\n"
           "const uint PL_BVH_NODE_RECORDS = " + records(sizeof(BvhNode)) + ";\n"
           "const uint PL_SCENE_TRIANGLE_RECORDS = " + records(sizeof(SceneTriangle)) + ";\n"
           "const uint PL_BVH_LEAF_COUNT_BITS = " + std::to_string(kLeafCountBits) + "u;\n";
}

} // namespace pl::scene::gpu
