#include "scene/mesh.hpp"

#include <algorithm>
#include <map>

namespace pl::scene {

std::vector<uint32_t> adjacency_indices(const Mesh& mesh) {
    const std::vector<uint32_t> weld = weld_positions(mesh);
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
