// The CPU mesh a [meshes] entry describes: generated or loaded, then simplified when it says
// `simplify = { ... }`. One function, so every consumer of a mesh (vertex buffers, and anything
// built from its triangles) sees the same geometry.
#pragma once

#include "graph/desc.hpp"
#include "scene/simplify.hpp"

#include <optional>

namespace pl::exec {

struct CpuMesh {
    scene::Mesh mesh;
    std::vector<scene::MorphVertex> morph;           // per vertex, when simplify.morph is set
    std::optional<scene::SimplifyStats> simplified;  // what the simplifier did
    double simplify_ms = 0;                          // its CPU time (reported by `passlab bench`)
};

scene::SimplifyOptions simplify_options(const graph::MeshSimplifyDesc& d);

// Errors carry the mesh's name and location.
Result<CpuMesh> load_graph_mesh(const graph::GraphDesc& g, const graph::MeshDesc& md);

} // namespace pl::exec
