// Full-sweep SAH build (MacDonald & Booth 1990; the seed's "sweep triangle-AABB-wise surface area
// heuristics", 002_644d46bdce7e5305.txt L1914-1920). Each node's triangles are kept sorted by
// centroid along all three axes at once; a split partitions the other two orders stably, so the
// whole build is O(n log n) after the initial sorts and never re-sorts. The stack is explicit:
// an adversarial mesh can make the tree as deep as it has triangles.
#include "scene/bvh.hpp"

#include <algorithm>
#include <cstdlib>

namespace pl::scene {

namespace {

// Relative costs of visiting a node and of testing a triangle. In a stackless GPU traversal both
// are a handful of loads and a few dozen flops, so they are taken as equal.
constexpr float kTraversalCost = 1.0f;
constexpr float kIntersectCost = 1.0f;

struct Split {
    int axis = -1;
    uint32_t left = 0;  // number of triangles on the left (1..n-1)
    float cost = 0;
};

class Builder {
  public:
    Builder(const std::vector<TrianglePositions>& tris, int leaf_size)
        : leaf_size_(static_cast<uint32_t>(std::clamp(leaf_size, 1, kMaxLeafSize))) {
        const uint32_t n = static_cast<uint32_t>(tris.size());
        boxes_.resize(n);
        centroids_.resize(n);
        for (uint32_t i = 0; i < n; ++i) {
            for (const glm::vec3& p : tris[i]) boxes_[i].grow(p);
            centroids_[i] = (tris[i][0] + tris[i][1] + tris[i][2]) / 3.0f;
        }
        for (int a = 0; a < 3; ++a) {
            auto& s = sorted_[static_cast<size_t>(a)];
            s.resize(n);
            for (uint32_t i = 0; i < n; ++i) s[i] = i;
            // A total order (ties by index): the result does not depend on the sort algorithm.
            std::sort(s.begin(), s.end(), [&](uint32_t x, uint32_t y) {
                float cx = centroids_[x][a], cy = centroids_[y][a];
                return cx < cy || (cx == cy && x < y);
            });
        }
        left_.assign(n, 0);
        scratch_.resize(n);
        suffix_.resize(n + 1);
    }

    Bvh run() {
        Bvh out;
        const uint32_t n = static_cast<uint32_t>(boxes_.size());
        if (n == 0) return out;
        struct Task {
            uint32_t begin, end, parent;
        };
        std::vector<Task> stack{{0, n, UINT32_MAX}};
        std::vector<uint32_t> parent;
        while (!stack.empty()) {
            Task t = stack.back();
            stack.pop_back();
            const uint32_t index = static_cast<uint32_t>(out.nodes.size());
            BvhNode node{};
            for (uint32_t k = t.begin; k < t.end; ++k) node.box.grow(boxes_[sorted_[0][k]]);
            out.nodes.push_back(node);
            parent.push_back(t.parent);
            const uint32_t count = t.end - t.begin;
            Split s = count > 1 ? best_split(t.begin, t.end) : Split{};
            const float leaf_cost = kIntersectCost * float(count) * node.box.half_area();
            if (count <= leaf_size_ && (s.axis < 0 || leaf_cost <= s.cost)) {
                out.nodes[index].first = static_cast<uint32_t>(out.triangles.size());
                out.nodes[index].count = count;
                for (uint32_t k = t.begin; k < t.end; ++k) out.triangles.push_back(sorted_[0][k]);
                continue;
            }
            partition(t.begin, t.end, s);
            const uint32_t mid = t.begin + s.left;
            // Right pushed first so that the left subtree directly follows its parent (preorder).
            stack.push_back({mid, t.end, index});
            stack.push_back({t.begin, mid, index});
        }
        // skip = index + subtree size; sizes accumulate from the last node back to the root
        // because every child comes after its parent in preorder.
        std::vector<uint32_t> size(out.nodes.size(), 1);
        for (size_t i = out.nodes.size(); i-- > 1;) size[parent[i]] += size[i];
        for (size_t i = 0; i < out.nodes.size(); ++i) out.nodes[i].skip = static_cast<uint32_t>(i) + size[i];
        return out;
    }

  private:
    // The cheapest split over every position of every axis's order. The SAH cost is kept
    // multiplied by the parent's area (no division), so flat and point-sized nodes compare
    // without 0/0; equal costs prefer the more balanced split, then the lower axis and position.
    Split best_split(uint32_t begin, uint32_t end) {
        const uint32_t n = end - begin;
        Split best;
        uint32_t best_imbalance = UINT32_MAX;
        Aabb all;
        for (uint32_t k = begin; k < end; ++k) all.grow(boxes_[sorted_[0][k]]);
        const float parent_area = all.half_area();
        for (int a = 0; a < 3; ++a) {
            const auto& s = sorted_[static_cast<size_t>(a)];
            Aabb right;
            suffix_[n] = 0;
            for (uint32_t k = n; k-- > 1;) {
                right.grow(boxes_[s[begin + k]]);
                suffix_[k] = right.half_area();
            }
            Aabb left;
            for (uint32_t k = 1; k < n; ++k) {
                left.grow(boxes_[s[begin + k - 1]]);
                float cost = kTraversalCost * parent_area +
                             kIntersectCost * (left.half_area() * float(k) + suffix_[k] * float(n - k));
                uint32_t imbalance = static_cast<uint32_t>(std::abs(int64_t(2) * k - n));
                if (best.axis < 0 || cost < best.cost || (cost == best.cost && imbalance < best_imbalance)) {
                    best = {a, k, cost};
                    best_imbalance = imbalance;
                }
            }
        }
        return best;
    }

    // Splits [begin, end) into the split axis's first `s.left` triangles and the rest, keeping
    // every axis's order sorted (a stable partition of the other two).
    void partition(uint32_t begin, uint32_t end, const Split& s) {
        const auto& chosen = sorted_[static_cast<size_t>(s.axis)];
        for (uint32_t k = begin; k < end; ++k) left_[chosen[k]] = k < begin + s.left;
        for (int a = 0; a < 3; ++a) {
            if (a == s.axis) continue;
            auto& order = sorted_[static_cast<size_t>(a)];
            uint32_t l = begin, r = 0;
            for (uint32_t k = begin; k < end; ++k) {
                if (left_[order[k]]) order[l++] = order[k];
                else scratch_[r++] = order[k];
            }
            std::copy(scratch_.begin(), scratch_.begin() + r, order.begin() + l);
        }
    }

    uint32_t leaf_size_;
    std::vector<Aabb> boxes_;
    std::vector<glm::vec3> centroids_;
    std::array<std::vector<uint32_t>, 3> sorted_;  // a node's range holds the same set in all three
    std::vector<uint8_t> left_;
    std::vector<uint32_t> scratch_;
    std::vector<float> suffix_;
};

} // namespace

Bvh build_bvh(const std::vector<TrianglePositions>& triangles, int leaf_size) {
    return Builder(triangles, leaf_size).run();
}

} // namespace pl::scene
