// The simplifier's working state, shared by simplify.cpp (set-up, the queue, output) and
// collapse.cpp (the legality tests and the collapse itself). Internal to host/scene.
#pragma once

#include "scene/quadric.hpp"
#include "scene/simplify.hpp"

#include <array>
#include <optional>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pl::scene::detail {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t}; }

// Border edges weigh this much more than the surface (per unit area), so moving a border by d
// costs like moving 100x its adjacent area by d: enough that borders erode last, small enough
// that costs stay well inside double precision.
constexpr double kBorderPenalty = 100.0;

struct Point {
    Vec3 pos{};
    Quadric q;
    std::vector<uint32_t> tris, edges, wedges;
    bool border = false, locked = false;  // locked: on a non-manifold edge, never moved
};

struct Wedge {
    uint32_t point = 0;
    uint32_t merged_into = 0;  // itself while alive
    Vertex v{};                // attributes (position comes from the point)
};

struct Edge {
    uint32_t a = 0, b = 0;
    double cost = 0;
    Vec3 pos{};
    bool alive = true, dirty = false, queued = false;
};

struct Entry {
    double cost;
    uint32_t edge;
    // std::priority_queue pops the largest: invert, and break ties by the lower edge index.
    bool operator<(const Entry& o) const { return cost != o.cost ? cost > o.cost : edge > o.edge; }
};

inline uint64_t edge_key(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a); }

class Simplifier {
public:
    explicit Simplifier(const Mesh& m);
    void run(size_t goal, std::optional<double> max_error);
    Mesh extract(std::vector<uint32_t>* wedge_of_vertex, std::vector<uint32_t>* source) const;
    uint32_t final_wedge(uint32_t w) const {
        while (wedges_[w].merged_into != w) w = wedges_[w].merged_into;
        return w;
    }
    Vec3 wedge_position(uint32_t w) const { return points_[wedges_[w].point].pos; }
    const Vertex& wedge_attributes(uint32_t w) const { return wedges_[w].v; }
    size_t live_triangles() const { return live_; }
    SimplifyStats stats;

private:
    uint32_t corner_point(uint32_t t, int c) const { return wedges_[tris_[t][static_cast<size_t>(c)]].point; }
    bool has_point(uint32_t t, uint32_t p) const {
        return corner_point(t, 0) == p || corner_point(t, 1) == p || corner_point(t, 2) == p;
    }
    uint32_t other(const Edge& e, uint32_t p) const { return e.a == p ? e.b : e.a; }
    void cost(Edge& e);
    bool legal(const Edge& e) const;
    bool wedge_map(uint32_t keep, uint32_t gone, std::vector<std::pair<uint32_t, uint32_t>>& map) const;
    void collapse(uint32_t edge, uint32_t keep, uint32_t gone, const std::vector<std::pair<uint32_t, uint32_t>>& map);
    void push(uint32_t e) {
        edges_[e].queued = true;
        queue_.push({edges_[e].cost, e});
    }

    std::vector<Point> points_;
    std::vector<Wedge> wedges_;
    std::vector<std::array<uint32_t, 3>> tris_;  // wedge per corner
    std::vector<uint32_t> source_;               // input triangle index of each
    std::vector<Vec3> normal0_;                  // and its unit normal there
    std::vector<bool> tri_alive_;
    std::vector<Edge> edges_;
    std::unordered_map<uint64_t, uint32_t> edge_of_;
    std::priority_queue<Entry> queue_;
    size_t live_ = 0;
    bool seeded_ = false;
};

} // namespace pl::scene::detail
