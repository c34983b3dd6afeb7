// The contents of a host-built scene buffer ([buffers] generator = "bvh" | "triangles"): meshes
// packed into the layout of scene/scene_gpu.hpp, each with its own object-space BVH.
#pragma once

#include "scene/bvh.hpp"
#include "scene/mesh.hpp"

#include <string>
#include <vector>

namespace pl::scene {

// The mesh's triangles as corner positions, in index-list order (triangle k = indices[3k..]).
std::vector<TrianglePositions> mesh_triangles(const Mesh& m);

struct SceneInput {
    std::string name;  // for messages
    const Mesh* mesh = nullptr;
};

// 32-bit words ready for upload: header, mesh table, nodes (with_bvh only), triangles. Every
// mesh gets a BVH of leaves of at most `leaf_size` triangles; a mesh without triangles gets no
// nodes and an empty range. A non-finite vertex position or an index past the vertices is an
// error naming the mesh. Identical input gives identical words.
Result<std::vector<uint32_t>> build_scene_buffer(const std::vector<SceneInput>& meshes, bool with_bvh, int leaf_size);

} // namespace pl::scene
