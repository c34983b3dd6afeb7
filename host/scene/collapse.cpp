// The edge collapse of scene/simplify.cpp: whether one is legal (topology, orientation, seams)
// and performing it (quadrics summed, faces and edges re-linked, neighbours set dirty as the
// lazy greedy loop of 000_c9f7e5de708ecbb3.txt L5998-6002 says: "perform operation, for each
// neighbor set dirty flag to true").
#include "scene/simplify_state.hpp"

#include <algorithm>
#include <cmath>

namespace pl::scene::detail {

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

} // namespace pl::scene::detail
