// Bounding-volume hierarchy over one mesh's triangles, built on the host with the surface area
// heuristic and flattened in depth-first preorder with skip indices, so that a shader traverses
// it without a stack (002_644d46bdce7e5305.txt L1902-1922: "converted to skip-lists with a
// depth-first tree preorder traversal"; L2104-2129: a hit goes to i + 1, a miss to skipToNode).
// Pure CPU code; the GPU layout of the result is in scene/scene_gpu.hpp.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace pl::scene {

struct Aabb {
    glm::vec3 lo{3.4e38f}, hi{-3.4e38f};  // empty: lo > hi
    void grow(const glm::vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    // Half the surface area (the SAH only compares ratios); 0 for an empty or flat-point box.
    float half_area() const {
        glm::vec3 d = glm::max(hi - lo, glm::vec3(0));
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

using TrianglePositions = std::array<glm::vec3, 3>;

struct BvhNode {
    Aabb box;        // union of the triangles below: children's boxes lie inside
    uint32_t skip;   // preorder index of the next node when this one is missed: index + subtree size
    uint32_t first;  // leaf: first entry in Bvh::triangles (0 for inner nodes)
    uint32_t count;  // leaf: number of triangles (1..leaf_size); 0 for an inner node
};

struct Bvh {
    std::vector<BvhNode> nodes;       // depth-first preorder: a node's first child is the next node
    std::vector<uint32_t> triangles;  // input triangle indices in leaf order; each exactly once
};

// Largest leaf_size: the GPU node packs the leaf's triangle count into 4 bits (scene_gpu.hpp).
inline constexpr int kMaxLeafSize = 15;

// Full-sweep SAH (every split between consecutive centroids along x, y and z is evaluated, not
// bins), with leaves of at most `leaf_size` triangles (1..kMaxLeafSize). Deterministic: ties
// are broken by triangle index and then by balance, so equal input gives an identical tree.
// Degenerate input (identical centroids, zero-area or zero-extent triangles) still splits by
// index, so the leaf bound always holds. An empty input gives an empty tree.
Bvh build_bvh(const std::vector<TrianglePositions>& triangles, int leaf_size);

} // namespace pl::scene
