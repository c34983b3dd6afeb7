// Edge-collapse simplification with quadric error metrics, in the lazy greedy form of
// 000_c9f7e5de708ecbb3.txt L5969-6000:
//   compute costs for each possible operation, insert them into the queue, dirty = false;
//   while the queue is not empty: extract the head; if it is dirty, re-compute its cost,
//   clear the flag and re-insert it; else perform it and set its neighbours dirty.
// The operations are the mesh's edges (pairs joined by an edge; no "virtual pairs" across gaps,
// so the topology never changes). Costs are the quadric of L6005-6033 at the best position.
//
// Choices, and why:
// - Face quadrics are weighted by triangle area (Garland's thesis, sec. 5): the metric then
//   measures the surface, not its tessellation - a finely tessellated patch does not weigh more
//   than a coarse one of the same size - and zero-area triangles add nothing.
// - Borders get penalty quadrics (Garland & Heckbert sec. 6.1): a plane through each border
//   edge, perpendicular to its face, weighted kBorderPenalty x edge length^2. Unlike forbidding
//   border collapses, this lets collinear border vertices merge at zero cost (a subdivided
//   plane reduces to its 4 corners) while corners and curved borders keep their shape.
// - A collapse is refused when it would flip or zero a surviving face (against its current and
//   its input orientation), break the link condition
//   (the two endpoints' common neighbours must be exactly the edge's opposite vertices, so the
//   mesh stays manifold), pinch two borders together through an interior edge, or tear a uv/normal
//   seam (below).
// - Seams: vertices split for attributes ("wedges") share one welded point. Collapsing point r
//   into point k maps each wedge of r to the wedge of k it meets in a triangle that the collapse
//   removes; a wedge of r that meets none (the edge leaves the seam) makes that direction
//   illegal. Mapped wedge pairs get their attributes interpolated at the new position.
#include "scene/simplify.hpp"

#include "scene/quadric.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <queue>
#include <unordered_map>

namespace pl::scene {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t}; }

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

uint64_t edge_key(uint32_t a, uint32_t b) { return a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a); }

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

Simplifier::Simplifier(const Mesh& m) {
    std::vector<uint32_t> weld = weld_positions(m);
    uint32_t np = 0;
    for (uint32_t w : weld) np = std::max(np, w + 1);
    points_.resize(np);
    wedges_.resize(m.vertices.size());
    for (uint32_t i = 0; i < m.vertices.size(); ++i) {
        wedges_[i] = {weld[i], i, m.vertices[i]};
        points_[weld[i]].wedges.push_back(i);
        for (size_t k = 0; k < 3; ++k) points_[weld[i]].pos[k] = m.vertices[i].position[k];
    }
    // Triangles whose corners weld together (a UV sphere's pole rows, a Bezier patch's collapsed
    // edge) have no area and no orientation: dropped, and not counted as input.
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        std::array<uint32_t, 3> w = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
        uint32_t p0 = weld[w[0]], p1 = weld[w[1]], p2 = weld[w[2]];
        if (p0 == p1 || p1 == p2 || p0 == p2) continue;
        uint32_t id = static_cast<uint32_t>(tris_.size());
        tris_.push_back(w);
        source_.push_back(static_cast<uint32_t>(t / 3));
        for (uint32_t p : {p0, p1, p2}) points_[p].tris.push_back(id);
        // Face quadric, area-weighted.
        Vec3 n = cross(sub(points_[p1].pos, points_[p0].pos), sub(points_[p2].pos, points_[p0].pos));
        double len = std::sqrt(dot(n, n));
        normal0_.push_back(len > 0 ? Vec3{n[0] / len, n[1] / len, n[2] / len} : Vec3{0, 0, 0});
        if (len > 0) {
            Vec3 u = normal0_.back();
            Quadric q = Quadric::plane(u, -dot(u, points_[p0].pos), 0.5 * len);
            for (uint32_t p : {p0, p1, p2}) points_[p].q += q;
        }
        // Edges, in order of first appearance (deterministic ids).
        for (int c = 0; c < 3; ++c) {
            uint32_t a = weld[w[static_cast<size_t>(c)]], b = weld[w[static_cast<size_t>((c + 1) % 3)]];
            auto [it, fresh] = edge_of_.emplace(edge_key(a, b), static_cast<uint32_t>(edges_.size()));
            if (fresh) {
                edges_.push_back({std::min(a, b), std::max(a, b)});
                points_[a].edges.push_back(it->second);
                points_[b].edges.push_back(it->second);
            }
        }
    }
    tri_alive_.assign(tris_.size(), true);
    stats.min_cost = HUGE_VAL;
    live_ = tris_.size();
    stats.input_triangles = live_;
    // Border edges (one face) get penalty planes; non-manifold ones (three or more) lock their ends.
    for (Edge& e : edges_) {
        std::vector<uint32_t> faces;
        for (uint32_t t : points_[e.a].tris)
            if (has_point(t, e.b)) faces.push_back(t);
        if (faces.size() >= 3) points_[e.a].locked = points_[e.b].locked = true;
        if (faces.size() != 1) continue;
        points_[e.a].border = points_[e.b].border = true;
        const Vec3 &pa = points_[e.a].pos, &pb = points_[e.b].pos;
        uint32_t t = faces[0];
        Vec3 n = cross(sub(points_[corner_point(t, 1)].pos, points_[corner_point(t, 0)].pos),
                       sub(points_[corner_point(t, 2)].pos, points_[corner_point(t, 0)].pos));
        Vec3 out = cross(sub(pb, pa), n);  // in the face's plane, perpendicular to the edge
        double len = std::sqrt(dot(out, out));
        if (!(len > 0)) continue;
        Vec3 u = {out[0] / len, out[1] / len, out[2] / len};
        Vec3 d = sub(pb, pa);
        Quadric q = Quadric::plane(u, -dot(u, pa), kBorderPenalty * dot(d, d));
        q.weight = 0;  // the error's denominator is surface area only
        points_[e.a].q += q;
        points_[e.b].q += q;
    }
}

// The cost of collapsing edge e and where its vertex goes: the quadric's minimiser when the
// system is regular and the minimiser lies near the edge; otherwise the best of the endpoints
// and the midpoint (ties: a, then b, then midpoint). The distance guard matters on nearly flat
// neighbourhoods: a barely regular system can put the optimum far off the surface, and a vertex
// thrown a mesh-width away is exactly the spike simplification must not make.
void Simplifier::cost(Edge& e) {
    const Point &a = points_[e.a], &b = points_[e.b];
    Quadric q = a.q + b.q;
    Vec3 mid = lerp(a.pos, b.pos, 0.5), opt{};
    Vec3 ab = sub(b.pos, a.pos);
    if (q.optimum(opt) && dot(sub(opt, mid), sub(opt, mid)) <= dot(ab, ab)) {
        e.pos = opt;
        e.cost = q.evaluate(opt);
    } else {
        e.pos = a.pos;
        e.cost = q.evaluate(a.pos);
        for (const Vec3& c : {b.pos, mid}) {
            double k = q.evaluate(c);
            if (k < e.cost) e.cost = k, e.pos = c;
        }
    }
    if (a.locked) e.pos = a.pos, e.cost = q.evaluate(a.pos);
    if (b.locked) e.pos = b.pos, e.cost = q.evaluate(b.pos);
    stats.min_cost = std::min(stats.min_cost, e.cost);
}

// Topology and geometry tests, independent of which endpoint's id survives.
bool Simplifier::legal(const Edge& e) const {
    const Point &a = points_[e.a], &b = points_[e.b];
    if (a.locked && b.locked) return false;
    // Link condition: common neighbours == the vertices opposite the edge.
    std::vector<uint32_t> na, nb, opposite;
    for (uint32_t x : a.edges) na.push_back(other(edges_[x], e.a));
    for (uint32_t x : b.edges) nb.push_back(other(edges_[x], e.b));
    std::sort(na.begin(), na.end());
    std::sort(nb.begin(), nb.end());
    std::vector<uint32_t> common;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    for (uint32_t t : a.tris)
        if (has_point(t, e.b))
            for (int c = 0; c < 3; ++c)
                if (corner_point(t, c) != e.a && corner_point(t, c) != e.b) opposite.push_back(corner_point(t, c));
    std::sort(opposite.begin(), opposite.end());
    if (common != opposite) return false;
    // A face of b that would land on an existing face of a (a tetrahedron folding flat).
    auto others = [&](uint32_t t, uint32_t p) {
        std::array<uint32_t, 2> o{};
        size_t n = 0;
        for (int c = 0; c < 3; ++c)
            if (corner_point(t, c) != p && n < 2) o[n++] = corner_point(t, c);
        if (o[0] > o[1]) std::swap(o[0], o[1]);
        return o;
    };
    for (uint32_t tb : b.tris) {
        if (has_point(tb, e.a)) continue;
        for (uint32_t ta : a.tris)
            if (!has_point(ta, e.b) && others(ta, e.a) == others(tb, e.b)) return false;
    }
    // Two borders joined by an interior edge would meet in a non-manifold vertex.
    if (a.border && b.border && opposite.size() != 1) return false;
    // Every surviving face around either end keeps its orientation and some area.
    for (uint32_t end : {e.a, e.b})
        for (uint32_t t : points_[end].tris) {
            if (has_point(t, other(e, end))) continue;  // removed by the collapse
            Vec3 p[3], q[3];
            for (int c = 0; c < 3; ++c) {
                p[c] = points_[corner_point(t, c)].pos;
                q[c] = corner_point(t, c) == end ? e.pos : p[c];
            }
            Vec3 n0 = cross(sub(p[1], p[0]), sub(p[2], p[0])), n1 = cross(sub(q[1], q[0]), sub(q[2], q[0]));
            double l0 = dot(n0, n0), l1 = dot(n1, n1);
            double longest = std::max({dot(sub(q[1], q[0]), sub(q[1], q[0])), dot(sub(q[2], q[1]), sub(q[2], q[1])),
                                       dot(sub(q[0], q[2]), sub(q[0], q[2]))});
            if (!(l1 > 1e-24 * longest * longest)) return false;  // zero area: no normal left
            if (l0 > 0 && !(dot(n0, n1) > 0)) return false;        // flipped
            // Nor turned away from the face it was in the input: many small turns that each pass
            // the test above can still fold a face over (seen on the teapot's spout at 10%).
            if (!(dot(normal0_[t], n1) >= 0)) return false;
        }
    return true;
}

// Which wedge of `keep` each wedge of `gone` becomes (see the header comment on seams). False
// when a wedge of `gone` that a surviving face uses meets no wedge of `keep`, or two of them.
bool Simplifier::wedge_map(uint32_t keep, uint32_t gone, std::vector<std::pair<uint32_t, uint32_t>>& map) const {
    map.clear();
    auto find = [&](uint32_t w) -> const std::pair<uint32_t, uint32_t>* {
        for (const auto& m : map)
            if (m.first == w) return &m;
        return nullptr;
    };
    for (uint32_t t : points_[gone].tris) {
        if (!has_point(t, keep)) continue;
        uint32_t wg = 0, wk = 0;
        for (int c = 0; c < 3; ++c) {
            if (corner_point(t, c) == gone) wg = tris_[t][static_cast<size_t>(c)];
            if (corner_point(t, c) == keep) wk = tris_[t][static_cast<size_t>(c)];
        }
        if (const auto* m = find(wg)) {
            if (m->second != wk) return false;
        } else {
            map.push_back({wg, wk});
        }
    }
    for (uint32_t t : points_[gone].tris)
        for (int c = 0; c < 3; ++c)
            if (corner_point(t, c) == gone && !find(tris_[t][static_cast<size_t>(c)])) return false;
    return true;
}

void Simplifier::collapse(uint32_t edge, uint32_t keep, uint32_t gone, const std::vector<std::pair<uint32_t, uint32_t>>& map) {
    Edge& e = edges_[edge];
    Point &k = points_[keep], &g = points_[gone];
    // Attributes of each mapped pair, interpolated at the new position's place along the edge.
    Vec3 dir = sub(g.pos, k.pos);
    double t = std::clamp(dot(sub(e.pos, k.pos), dir) / std::max(dot(dir, dir), 1e-300), 0.0, 1.0);
    for (const auto& [wg, wk] : map) {
        Vertex& a = wedges_[wk].v;
        const Vertex& b = wedges_[wg].v;
        for (int c = 0; c < 3; ++c) a.normal[c] += float((b.normal[c] - a.normal[c]) * t);
        for (int c = 0; c < 2; ++c) a.uv[c] += float((b.uv[c] - a.uv[c]) * t);
        for (int c = 0; c < 3; ++c) a.tangent[c] += float((b.tangent[c] - a.tangent[c]) * t);
        for (float* v : {a.normal, a.tangent}) {
            float l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (l > 0) v[0] /= l, v[1] /= l, v[2] /= l;
        }
        wedges_[wg].merged_into = wk;
    }
    // Wedges of `gone` no face uses any more (their faces died earlier) still need a successor:
    // a geomorph target follows merged_into to the coarse mesh.
    for (uint32_t w : g.wedges)
        if (wedges_[w].merged_into == w) wedges_[w].merged_into = map.empty() ? k.wedges.front() : map.front().second;
    g.wedges.clear();
    k.pos = e.pos;
    k.q += g.q;
    k.border = k.border || g.border;
    k.locked = k.locked || g.locked;
    // Faces: those on the edge die, the others of `gone` now use `keep`'s wedges.
    std::vector<uint32_t> tris;
    for (uint32_t f : k.tris)
        if (!has_point(f, gone)) tris.push_back(f);
    for (uint32_t f : g.tris) {
        if (has_point(f, keep)) {
            tri_alive_[f] = false;
            --live_;
            for (int c = 0; c < 3; ++c)  // and off the third corner's list
                if (uint32_t p = corner_point(f, c); p != keep && p != gone) {
                    auto& pt = points_[p].tris;
                    pt.erase(std::remove(pt.begin(), pt.end(), f), pt.end());
                }
            continue;
        }
        for (uint32_t& w : tris_[f])
            if (wedges_[w].point == gone)
                for (const auto& m : map)
                    if (m.first == w) {
                        w = m.second;
                        break;
                    }
        tris.push_back(f);
    }
    std::sort(tris.begin(), tris.end());
    k.tris = std::move(tris);
    g.tris.clear();
    // Edges: (gone, x) becomes (keep, x), or dies where (keep, x) exists; the edge itself dies.
    e.alive = false;
    edge_of_.erase(edge_key(e.a, e.b));
    for (uint32_t x : g.edges) {
        if (x == edge) continue;
        Edge& ge = edges_[x];
        uint32_t o = other(ge, gone);
        edge_of_.erase(edge_key(gone, o));
        auto it = edge_of_.find(edge_key(keep, o));
        if (it != edge_of_.end()) {
            ge.alive = false;
            auto& oe = points_[o].edges;
            oe.erase(std::remove(oe.begin(), oe.end(), x), oe.end());
            continue;
        }
        ge.a = std::min(keep, o), ge.b = std::max(keep, o);
        edge_of_.emplace(edge_key(keep, o), x);
        k.edges.push_back(x);
    }
    k.edges.erase(std::remove(k.edges.begin(), k.edges.end(), edge), k.edges.end());
    std::sort(k.edges.begin(), k.edges.end());
    g.edges.clear();
    // Dirty: every edge at `keep` (its quadric and position changed). Edges one ring further
    // keep their cost, but their legality depends on `keep`'s faces: re-queue those that were
    // refused, so nothing stays blocked by a neighbourhood that has since changed.
    for (uint32_t x : k.edges) {
        edges_[x].dirty = true;
        if (!edges_[x].queued) push(x);
        for (uint32_t y : points_[other(edges_[x], keep)].edges)
            if (edges_[y].alive && !edges_[y].queued) push(y);
    }
    ++stats.collapses;
}

void Simplifier::run(size_t goal, std::optional<double> max_error) {
    if (!seeded_) {  // "compute costs for each possible operation, insert them into queue"
        seeded_ = true;
        for (uint32_t i = 0; i < edges_.size(); ++i) {
            cost(edges_[i]);
            push(i);
        }
    }
    std::vector<std::pair<uint32_t, uint32_t>> map;
    while (live_ > goal && !queue_.empty()) {
        Entry head = queue_.top();
        queue_.pop();
        Edge& e = edges_[head.edge];
        if (!e.alive) continue;  // merged away after it was queued
        if (e.dirty) {           // "re-compute cost, set dirty flag to false, re-insert"
            cost(e);
            e.dirty = false;
            push(head.edge);
            ++stats.recosted;
            continue;
        }
        e.queued = false;
        double err = collapse_error(e.cost, points_[e.a].q.weight + points_[e.b].q.weight);
        if (max_error && err > *max_error) continue;
        if (!legal(e)) {
            ++stats.rejected;
            continue;
        }
        // Keep the id of the endpoint nearer the new position (its unmapped seam wedges then move
        // least); fall back to the other direction when the seam mapping forbids it.
        uint32_t keep = e.a, gone = e.b;
        if (dot(sub(e.pos, points_[e.b].pos), sub(e.pos, points_[e.b].pos)) <
            dot(sub(e.pos, points_[e.a].pos), sub(e.pos, points_[e.a].pos)))
            std::swap(keep, gone);
        if (points_[keep].locked != points_[gone].locked && points_[gone].locked) std::swap(keep, gone);
        if (!wedge_map(keep, gone, map)) {
            std::swap(keep, gone);
            if (points_[gone].locked || !wedge_map(keep, gone, map)) {
                ++stats.rejected;
                continue;
            }
        }
        stats.max_error = std::max(stats.max_error, err);
        collapse(head.edge, keep, gone, map);
    }
}

Mesh Simplifier::extract(std::vector<uint32_t>* wedge_of_vertex, std::vector<uint32_t>* source) const {
    Mesh out;
    std::vector<uint32_t> index(wedges_.size(), UINT32_MAX);
    std::vector<uint32_t> used;
    for (size_t t = 0; t < tris_.size(); ++t)
        if (tri_alive_[t])
            for (uint32_t w : tris_[t]) used.push_back(w);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    for (uint32_t w : used) {
        index[w] = static_cast<uint32_t>(out.vertices.size());
        Vertex v = wedges_[w].v;
        for (size_t k = 0; k < 3; ++k) v.position[k] = float(points_[wedges_[w].point].pos[k]);
        out.vertices.push_back(v);
        if (wedge_of_vertex) wedge_of_vertex->push_back(w);
    }
    for (size_t t = 0; t < tris_.size(); ++t)
        if (tri_alive_[t]) {
            for (uint32_t w : tris_[t]) out.indices.push_back(index[w]);
            if (source) source->push_back(source_[t]);
        }
    compute_bounds(out);
    return out;
}

} // namespace

double collapse_error(double cost, double weight) { return weight > 0 ? std::sqrt(std::max(cost, 0.0) / weight) : 0.0; }

Simplified simplify(const Mesh& mesh, const SimplifyOptions& options) {
    Simplifier s(mesh);
    Simplified out;
    // A ratio scales the welded, non-degenerate input count (what a draw actually shows).
    auto goal = [&](const SimplifyTarget& t) -> size_t {
        if (t.triangles) return *t.triangles;
        if (t.ratio) return static_cast<size_t>(std::floor(*t.ratio * double(s.stats.input_triangles)));
        return 0;
    };
    s.run(goal(options.target), options.target.max_error);
    std::vector<uint32_t> wedge_of_vertex;
    out.mesh = s.extract(options.morph ? &wedge_of_vertex : nullptr, &out.source_triangle);
    if (options.morph) {
        s.run(goal(*options.morph), options.morph->max_error);
        s.stats.morph_triangles = s.live_triangles();
        out.morph.reserve(wedge_of_vertex.size());
        for (uint32_t w : wedge_of_vertex) {
            uint32_t f = s.final_wedge(w);
            Vec3 p = s.wedge_position(f);
            const Vertex& a = s.wedge_attributes(f);
            MorphVertex m{};
            for (size_t k = 0; k < 3; ++k) m.position[k] = float(p[k]), m.normal[k] = a.normal[k];
            m.uv[0] = a.uv[0], m.uv[1] = a.uv[1];
            out.morph.push_back(m);
        }
    }
    out.stats = s.stats;
    if (out.stats.min_cost == HUGE_VAL) out.stats.min_cost = 0;
    out.stats.output_triangles = out.mesh.indices.size() / 3;
    return out;
}

} // namespace pl::scene
