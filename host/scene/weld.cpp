// Welding by position: the seams generators and loaders split (for uv or normal) share one id.
#include "scene/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace pl::scene {

std::vector<uint32_t> weld_positions(const Mesh& mesh) {
    // Quantised to 1e-6 of the mesh's extent, not exact bits: a seam copy computed as sin(2 pi)
    // is -2.4e-16, not the 0 it duplicates.
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
    return weld;
}

} // namespace pl::scene
