// Edge-collapse simplification with quadric error metrics, in the lazy greedy form of
// 000_c9f7e5de708ecbb3.txt L5974-6002:
//   compute costs for each possible operation, insert them into the queue, dirty = false;
//   while the queue is not empty: extract the head; if it is dirty, re-compute its cost,
//   clear the flag and re-insert it; else perform it and set its neighbours dirty.
// The operations are the mesh's edges (pairs joined by an edge; no "virtual pairs" across gaps,
// so the topology never changes). Costs are the quadric of L6004-6033 at the best position.
// (The legality tests and the collapse itself are in collapse.cpp.)
//
// Choices, and why:
// - Face quadrics are weighted by triangle area (Garland's thesis, sec. 5): the metric then
//   measures the surface, not its tessellation - a finely tessellated patch does not weigh more
//   than a coarse one of the same size - and zero-area triangles add nothing.
// - Borders get penalty quadrics (Garland & Heckbert sec. 6.1): a plane through each border
//   edge, perpendicular to its face, weighted kBorderPenalty x edge length^2. Unlike forbidding
//   border collapses, this lets collinear border vertices merge at zero cost (a subdivided
//   plane reduces to its 4 corners) while corners and curved borders keep their shape.
// - A collapse is refused (collapse.cpp) when it would flip or zero a surviving face (against
//   its current and its input orientation), break the link condition (the two endpoints' common
//   neighbours must be exactly the edge's opposite vertices, so the mesh stays manifold), pinch
//   two borders together through an interior edge, or tear a uv/normal seam (below).
// - Seams: vertices split for attributes ("wedges") share one welded point. Collapsing point r
//   into point k maps each wedge of r to the wedge of k it meets in a triangle that the collapse
//   removes; a wedge of r that meets none (the edge leaves the seam) makes that direction
//   illegal. Mapped wedge pairs get their attributes interpolated at the new position.
#include "scene/simplify_state.hpp"

#include <algorithm>
#include <cmath>

namespace pl::scene {

namespace detail {

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

} // namespace detail

double collapse_error(double cost, double weight) { return weight > 0 ? std::sqrt(std::max(cost, 0.0) / weight) : 0.0; }

Simplified simplify(const Mesh& mesh, const SimplifyOptions& options) {
    detail::Simplifier s(mesh);
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
            detail::Vec3 p = s.wedge_position(f);
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
