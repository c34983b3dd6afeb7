#include "scene/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace pl::scene {

std::vector<uint32_t> adjacency_indices(const Mesh& mesh) {
    // Weld: one id per position, quantised to 1e-6 of the mesh's extent. Not exact bits: a seam
    // copy computed as sin(2 pi) is -2.4e-16, not the 0 it duplicates.
    float extent = 0.0f;
    for (int k = 0; k < 3; ++k) extent = std::max(extent, mesh.bounds_max[k] - mesh.bounds_min[k]);
    for (const auto& v : mesh.vertices)
        for (float c : v.position) extent = std::max(extent, 2.0f * std::fabs(c));
    const double step = std::max(1e-6 * extent, 1e-12);
    std::map<std::array<long long, 3>, uint32_t> ids;
    std::vector<uint32_t> weld(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        std::array<long long, 3> key;
        for (int k = 0; k < 3; ++k) key[static_cast<size_t>(k)] = std::llround(mesh.vertices[i].position[k] / step);
        weld[i] = ids.emplace(key, static_cast<uint32_t>(ids.size())).first->second;
    }
    // Directed welded edge (a -> b) of a triangle -> the vertex opposite it. A consistently
    // wound neighbour holds the same edge as b -> a.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> opposite;
    const auto& idx = mesh.indices;
    // Triangles with two welded corners (a UV sphere's pole rows) have no area and no facing:
    // they are nobody's neighbour.
    auto degenerate = [&](size_t t) {
        return weld[idx[t]] == weld[idx[t + 1]] || weld[idx[t + 1]] == weld[idx[t + 2]] || weld[idx[t]] == weld[idx[t + 2]];
    };
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        if (degenerate(t)) continue;
        for (int e = 0; e < 3; ++e) {
            uint32_t a = idx[t + e], b = idx[t + (e + 1) % 3], c = idx[t + (e + 2) % 3];
            opposite.emplace(std::make_pair(weld[a], weld[b]), c);
        }
    }
    std::vector<uint32_t> out;
    out.reserve(idx.size() * 2);
    for (size_t t = 0; t + 2 < idx.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            uint32_t a = idx[t + e], b = idx[t + (e + 1) % 3], c = idx[t + (e + 2) % 3];
            auto it = degenerate(t) ? opposite.end() : opposite.find({weld[b], weld[a]});
            out.push_back(a);
            out.push_back(it != opposite.end() ? it->second : c);
        }
    return out;
}

} // namespace pl::scene
