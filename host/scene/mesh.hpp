// CPU-side meshes: procedural generators and file loaders produce the same interleaved layout,
// which the executor uploads once and binds as vertex locations 0..3 (see docs/format.md).
#pragma once

#include "util/error.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::scene {

// Interleaved vertex; shaders read location 0 position, 1 normal, 2 uv, 3 tangent (xyz + w sign).
struct Vertex {
    float position[3];
    float normal[3];
    float uv[2];
    float tangent[4];
};
static_assert(sizeof(Vertex) == 12 * sizeof(float), "Vertex layout is part of the shader contract");

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;  // triangle list
    float bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};
};

// Generator names: plane, cube, sphere, torus, teapot. Arguments (all optional): size, segments,
// rings, radius, tube (torus minor radius), subdivisions (teapot patch tessellation).
std::vector<std::string> generator_names();
Result<Mesh> generate_mesh(const std::string& generator, const std::map<std::string, double>& args);

// Index list for VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY (geometry shaders that look
// at neighbouring triangles: silhouettes, fins): per triangle (v0, a01, v1, a12, v2, a20), a_ij
// the vertex opposite edge ij in the triangle across it. Vertices are matched by position, so
// the seams generators and loaders split (for uv or normal) do not cut the surface. An edge
// with no neighbour gets the triangle's own opposite vertex, which a geometry shader recognises
// (a_ij == the third corner) as an open border. Zero-area triangles (two
// corners at one position, as in a UV sphere's pole rows) are skipped as neighbours.
std::vector<uint32_t> adjacency_indices(const Mesh& mesh);

// One id per distinct position (quantised to 1e-6 of the mesh's extent), dense from 0 in order
// of first appearance: the topology under the seams. Used by adjacency and simplification.
std::vector<uint32_t> weld_positions(const Mesh& mesh);

// Loads .obj (tinyobjloader) or .gltf/.glb (tinygltf). Missing normals/tangents are computed.
Result<Mesh> load_mesh(const std::filesystem::path& file);

// Fills tangents from positions, normals and UVs (MikkTSpace-like per-triangle accumulation).
void compute_tangents(Mesh& m);
void compute_bounds(Mesh& m);

} // namespace pl::scene
