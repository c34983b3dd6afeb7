// Packs meshes and their BVHs into one buffer (layout: scene/scene_gpu.hpp).
#include "scene/scene_buffer.hpp"

#include "scene/scene_gpu.hpp"

#include <cmath>
#include <cstring>

namespace pl::scene {

namespace {

// A leaf's first triangle is stored above the count bits of BvhNode::leaf.
constexpr size_t kMaxTriangles = size_t(1) << (32 - gpu::kLeafCountBits);
static_assert(kMaxLeafSize < (1 << gpu::kLeafCountBits), "a leaf's count must fit its bits");

Status check_mesh(const SceneInput& in) {
    const Mesh& m = *in.mesh;
    for (size_t i = 0; i < m.indices.size(); ++i)
        if (m.indices[i] >= m.vertices.size())
            return make_error("mesh '" + in.name + "': index " + std::to_string(i) + " refers to vertex " +
                              std::to_string(m.indices[i]) + " of " + std::to_string(m.vertices.size()));
    for (size_t v = 0; v < m.vertices.size(); ++v)
        for (float c : m.vertices[v].position)
            if (!std::isfinite(c))
                return make_error("mesh '" + in.name + "': vertex " + std::to_string(v) +
                                  " has a non-finite position; a BVH cannot bound it");
    return ok_status();
}

void put(float dst[3], const glm::vec3& v) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
}

template <class T> void append(std::vector<uint32_t>& words, const std::vector<T>& items) {
    size_t at = words.size();
    words.resize(at + items.size() * sizeof(T) / 4);
    if (!items.empty()) std::memcpy(words.data() + at, items.data(), items.size() * sizeof(T));
}

} // namespace

std::vector<TrianglePositions> mesh_triangles(const Mesh& m) {
    std::vector<TrianglePositions> out(m.indices.size() / 3);
    for (size_t t = 0; t < out.size(); ++t)
        for (size_t c = 0; c < 3; ++c) {
            const float* p = m.vertices[m.indices[3 * t + c]].position;
            out[t][c] = glm::vec3(p[0], p[1], p[2]);
        }
    return out;
}

Result<std::vector<uint32_t>> build_scene_buffer(const std::vector<SceneInput>& meshes, bool with_bvh, int leaf_size) {
    std::vector<gpu::SceneMesh> table;
    std::vector<gpu::BvhNode> nodes;
    std::vector<gpu::SceneTriangle> triangles;
    for (size_t mi = 0; mi < meshes.size(); ++mi) {
        if (auto s = check_mesh(meshes[mi]); !s) return s.error();
        std::vector<TrianglePositions> tris = mesh_triangles(*meshes[mi].mesh);
        if (triangles.size() + tris.size() >= kMaxTriangles)
            return make_error("mesh '" + meshes[mi].name + "': the scene buffer would hold more than " +
                              std::to_string(kMaxTriangles - 1) + " triangles");
        const auto node_offset = static_cast<uint32_t>(nodes.size());
        const auto triangle_offset = static_cast<uint32_t>(triangles.size());
        std::vector<uint32_t> order(tris.size());
        for (uint32_t k = 0; k < order.size(); ++k) order[k] = k;
        if (with_bvh) {
            Bvh bvh = build_bvh(tris, leaf_size);
            for (const BvhNode& n : bvh.nodes) {
                gpu::BvhNode g{};
                put(g.lo, n.box.lo);
                put(g.hi, n.box.hi);
                g.skip = node_offset + n.skip;
                g.leaf = n.count ? (triangle_offset + n.first) << gpu::kLeafCountBits | n.count : 0;
                nodes.push_back(g);
            }
            order = std::move(bvh.triangles);
        }
        for (uint32_t k : order) {
            gpu::SceneTriangle g{};
            put(g.v0, tris[k][0]);
            put(g.v1, tris[k][1]);
            put(g.v2, tris[k][2]);
            g.mesh = static_cast<uint32_t>(mi);
            g.prim = k;
            triangles.push_back(g);
        }
        table.push_back({node_offset, static_cast<uint32_t>(nodes.size()) - node_offset, triangle_offset,
                         static_cast<uint32_t>(tris.size())});
    }
    gpu::SceneHeader h{};
    h.mesh_count = static_cast<uint32_t>(table.size());
    h.node_count = static_cast<uint32_t>(nodes.size());
    h.triangle_count = static_cast<uint32_t>(triangles.size());
    h.leaf_size = with_bvh ? static_cast<uint32_t>(leaf_size) : 0;
    h.meshes_at = 0;
    h.nodes_at = h.meshes_at + h.mesh_count * uint32_t(sizeof(gpu::SceneMesh) / gpu::kRecordBytes);
    h.triangles_at = h.nodes_at + h.node_count * uint32_t(sizeof(gpu::BvhNode) / gpu::kRecordBytes);
    h.record_count = h.triangles_at + h.triangle_count * uint32_t(sizeof(gpu::SceneTriangle) / gpu::kRecordBytes);
    std::vector<uint32_t> words;
    words.reserve(sizeof h / 4 + size_t(h.record_count) * 4);
    append(words, std::vector<gpu::SceneHeader>{h});
    append(words, table);
    append(words, nodes);
    append(words, triangles);
    return words;
}

} // namespace pl::scene
