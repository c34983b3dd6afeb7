// QEM simplification (scene/simplify): the quadric's algebra, the planar and closed-mesh
// properties the lecture's method promises, geomorph targets, determinism; and the figures the
// issue asks for (time, triangle counts, geometric error), printed, not checked against time.
#include "scene/quadric.hpp"
#include "scene/simplify.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

using namespace pl::scene;

namespace {

glm::dvec3 P(const Vertex& v) { return {v.position[0], v.position[1], v.position[2]}; }

Mesh gen(const std::string& name, std::map<std::string, double> args = {}) {
    auto m = generate_mesh(name, args);
    EXPECT_TRUE(m) << name;
    return m ? std::move(*m) : Mesh{};
}

Simplified to(const Mesh& m, double ratio) {
    SimplifyOptions o;
    o.target.ratio = ratio;
    return simplify(m, o);
}

// Welded directed edges -> how often each occurs. A closed, consistently oriented manifold has
// every edge exactly once in each direction; an open one may have a border edge once.
struct EdgeCensus {
    size_t interior = 0, border = 0, bad = 0;  // bad: >2 faces, or two faces wound alike
};
EdgeCensus census(const Mesh& m) {
    std::vector<uint32_t> w = weld_positions(m);
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        uint32_t a = w[m.indices[t]], b = w[m.indices[t + 1]], c = w[m.indices[t + 2]];
        if (a == b || b == c || a == c) continue;  // a pole row's sliver: not part of the surface
        for (int k = 0; k < 3; ++k) ++directed[{w[m.indices[t + k]], w[m.indices[t + (k + 1) % 3]]}];
    }
    EdgeCensus e;
    for (const auto& [k, n] : directed) {
        if (k.first > k.second && directed.count({k.second, k.first})) continue;  // counted from the other side
        auto back = directed.find({k.second, k.first});
        int m2 = back == directed.end() ? 0 : back->second;
        if (n == 1 && m2 == 1) ++e.interior;
        else if (n == 1 && m2 == 0) ++e.border;
        else ++e.bad;
    }
    return e;
}

// Distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    glm::dvec3 bp = p - b;
    double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    glm::dvec3 cp = p - c;
    double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    double den = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * den) + ac * (vc * den)));
}

// One-sided Hausdorff distance, sampled at the vertices of `from`: how far `from` strays from `to`.
double vertex_distance(const Mesh& from, const Mesh& to) {
    double worst = 0;
    for (const auto& v : from.vertices) {
        double best = INFINITY;
        for (size_t t = 0; t + 2 < to.indices.size(); t += 3)
            best = std::min(best, point_triangle(P(v), P(to.vertices[to.indices[t]]), P(to.vertices[to.indices[t + 1]]),
                                                 P(to.vertices[to.indices[t + 2]])));
        worst = std::max(worst, best);
    }
    return worst;
}

double extent(const Mesh& m) {
    return glm::length(glm::dvec3(m.bounds_max[0] - m.bounds_min[0], m.bounds_max[1] - m.bounds_min[1], m.bounds_max[2] - m.bounds_min[2]));
}

} // namespace

TEST(Quadric, PlaneGivesSquaredDistance) {
    std::array<double, 3> n = {2.0 / 3, -1.0 / 3, 2.0 / 3};  // unit
    Quadric q = Quadric::plane(n, -0.5, 1.0);
    for (std::array<double, 3> v : {std::array<double, 3>{0, 0, 0}, {1, 2, 3}, {-4, 0.5, 7}}) {
        double d = n[0] * v[0] + n[1] * v[1] + n[2] * v[2] - 0.5;
        EXPECT_NEAR(q.evaluate(v), d * d, 1e-12);
        EXPECT_NEAR(Quadric::plane(n, -0.5, 3.0).evaluate(v), 3 * d * d, 1e-12);  // the weight scales
    }
    // Q1 + Q2 is the sum of squared distances; three planes meet in one point, the optimum.
    Quadric s = Quadric::plane({1, 0, 0}, -1, 1) + Quadric::plane({0, 1, 0}, -2, 1) + Quadric::plane({0, 0, 1}, 3, 1);
    EXPECT_NEAR(s.evaluate({0, 0, 0}), 1 + 4 + 9, 1e-12);
    std::array<double, 3> o{};
    ASSERT_TRUE(s.optimum(o));
    EXPECT_NEAR(o[0], 1, 1e-12);
    EXPECT_NEAR(o[1], 2, 1e-12);
    EXPECT_NEAR(o[2], -3, 1e-12);
    EXPECT_NEAR(s.evaluate(o), 0, 1e-12);
    // Two planes: a line of minimisers, no unique optimum.
    EXPECT_FALSE((Quadric::plane({1, 0, 0}, 0, 1) + Quadric::plane({0, 1, 0}, 0, 1)).optimum(o));
}

TEST(Simplify, EveryCostIsNonNegative) {
    // Costs are sums of squares; rounding may go a hair below zero, never more. The scale of a
    // cost is area x distance^2 ~ extent^4 (1 here), so 1e-12 is ~1e4 ulps of double at 1.
    for (const char* name : {"teapot", "sphere", "torus", "plane"}) {
        Simplified s = to(gen(name, {{"segments", 24}}), 0.05);
        EXPECT_GE(s.stats.min_cost, -1e-12) << name;
        EXPECT_GT(s.stats.collapses, 0u) << name;
    }
    // The cube's every edge is a normal seam (each face has its own vertices): no collapse may
    // drag a face's corner off its seam, so nothing collapses, and nothing is torn.
    Simplified cube = to(gen("cube"), 0.05);
    EXPECT_EQ(cube.stats.collapses, 0u);
    EXPECT_EQ(cube.stats.output_triangles, 12u);
}

TEST(Simplify, PlanarRegionCollapsesAtZeroCostToItsBoundary) {
    Mesh plane = gen("plane", {{"segments", 32}, {"size", 2}});
    SimplifyOptions o;
    o.target.triangles = 2;
    o.target.max_error = 0.0;  // only zero-cost collapses are allowed, and they suffice
    Simplified s = simplify(plane, o);
    EXPECT_EQ(s.stats.input_triangles, 2048u);
    EXPECT_EQ(s.stats.output_triangles, 2u);
    EXPECT_EQ(s.stats.max_error, 0.0);
    ASSERT_EQ(s.mesh.vertices.size(), 4u);
    double area = 0;
    for (size_t t = 0; t < s.mesh.indices.size(); t += 3) {
        glm::dvec3 g = glm::cross(P(s.mesh.vertices[s.mesh.indices[t + 1]]) - P(s.mesh.vertices[s.mesh.indices[t]]),
                                  P(s.mesh.vertices[s.mesh.indices[t + 2]]) - P(s.mesh.vertices[s.mesh.indices[t]]));
        EXPECT_GT(g.y, 0.0);  // faces still up
        area += glm::length(g) / 2;
    }
    EXPECT_DOUBLE_EQ(area, 4.0);  // the boundary square, whole
    for (const auto& v : s.mesh.vertices) {
        EXPECT_EQ(v.position[1], 0.0f);  // exactly planar: not a bit off
        EXPECT_EQ(std::fabs(v.position[0]), 1.0f);
        EXPECT_EQ(std::fabs(v.position[2]), 1.0f);
        EXPECT_EQ(v.normal[1], 1.0f);
        // The uv field is affine in position, and stays so: u = x/2 + 1/2, v = z/2 + 1/2.
        EXPECT_FLOAT_EQ(v.uv[0], v.position[0] / 2 + 0.5f);
        EXPECT_FLOAT_EQ(v.uv[1], v.position[2] / 2 + 0.5f);
    }
    // Any intermediate count is reached at zero cost too, all vertices still on the plane.
    o.target.triangles = 200;
    Simplified mid = simplify(plane, o);
    EXPECT_LE(mid.stats.output_triangles, 200u);
    EXPECT_GE(mid.stats.output_triangles, 199u);
    for (const auto& v : mid.mesh.vertices) EXPECT_EQ(v.position[1], 0.0f);
    EXPECT_EQ(census(mid.mesh).bad, 0u);
}

TEST(Simplify, ClosedMeshReachesCountStaysManifoldNoFlips) {
    Mesh sphere = gen("sphere");  // 48 x 24: closed after welding its seam and poles
    EdgeCensus in = census(sphere);
    EXPECT_EQ(in.bad, 0u);
    EXPECT_EQ(in.border, 0u);
    for (double ratio : {0.5, 0.25, 0.1, 0.02}) {
        Simplified s = to(sphere, ratio);
        size_t want = static_cast<size_t>(ratio * double(s.stats.input_triangles));
        EXPECT_LE(s.stats.output_triangles, want) << ratio;
        EXPECT_GE(s.stats.output_triangles, want - 1) << ratio;  // an interior collapse removes 2
        EdgeCensus c = census(s.mesh);
        EXPECT_EQ(c.bad, 0u) << ratio;
        EXPECT_EQ(c.border, 0u) << ratio;  // still closed
        // Euler characteristic of a sphere: V - E + F = 2 over welded vertices.
        std::vector<uint32_t> w = weld_positions(s.mesh);
        uint32_t v = 0;
        for (uint32_t x : w) v = std::max(v, x + 1);
        EXPECT_EQ(int64_t(v) - int64_t(c.interior) + int64_t(s.stats.output_triangles), 2) << ratio;
        for (size_t t = 0; t < s.mesh.indices.size(); t += 3) {  // outward everywhere
            glm::dvec3 a = P(s.mesh.vertices[s.mesh.indices[t]]), b = P(s.mesh.vertices[s.mesh.indices[t + 1]]),
                       d = P(s.mesh.vertices[s.mesh.indices[t + 2]]);
            ASSERT_GT(glm::dot(glm::cross(b - a, d - a), a + b + d), 0.0) << ratio << " face " << t / 3;
        }
    }
}

TEST(Simplify, TeapotKeepsItsTopologyAndFacing) {
    Mesh teapot = gen("teapot");
    EdgeCensus in = census(teapot);
    for (double ratio : {0.5, 0.25, 0.1}) {
        Simplified s = to(teapot, ratio);
        size_t want = static_cast<size_t>(ratio * double(s.stats.input_triangles));
        EXPECT_LE(s.stats.output_triangles, want) << ratio;
        EXPECT_GE(s.stats.output_triangles, want - 1) << ratio;
        EdgeCensus c = census(s.mesh);
        EXPECT_LE(c.bad, in.bad) << ratio;  // no new non-manifold edges
        // No flips: every face still faces within 90 degrees of the input face it started as
        // (faces keep their identity; collapses only move their corners). This is stricter than
        // the per-collapse test the simplifier makes, which compares with the face's last state.
        ASSERT_EQ(s.source_triangle.size(), s.stats.output_triangles);
        auto normal = [](const Mesh& m, size_t t) {
            glm::dvec3 a = P(m.vertices[m.indices[3 * t]]), b = P(m.vertices[m.indices[3 * t + 1]]), c = P(m.vertices[m.indices[3 * t + 2]]);
            return glm::normalize(glm::cross(b - a, c - a));
        };
        size_t turned = 0;
        double worst = 1;
        for (size_t t = 0; t < s.stats.output_triangles; ++t) {
            double c = glm::dot(normal(s.mesh, t), normal(teapot, s.source_triangle[t]));
            worst = std::min(worst, c);
            turned += !(c > 0);
        }
        EXPECT_EQ(turned, 0u) << ratio << " (worst cosine " << worst << ")";
    }
}

TEST(Simplify, MaxErrorBoundsEveryCollapse) {
    // max_error alone simplifies as far as the bound allows, and no collapse made exceeds it; a
    // looser bound goes further.
    Mesh teapot = gen("teapot");
    size_t last = SIZE_MAX;
    for (double e : {0.001, 0.004, 0.016}) {
        SimplifyOptions o;
        o.target.max_error = e;
        Simplified s = simplify(teapot, o);
        EXPECT_LE(s.stats.max_error, e);
        EXPECT_GT(s.stats.collapses, 0u) << e;
        EXPECT_LT(s.stats.output_triangles, last) << e;
        last = s.stats.output_triangles;
    }
    // With a triangle target as well, whichever binds first stops the run.
    SimplifyOptions o;
    o.target.triangles = 3000;
    o.target.max_error = 0.016;
    EXPECT_LE(simplify(teapot, o).stats.output_triangles, 3000u);
}

TEST(Simplify, IsDeterministic) {
    Mesh teapot = gen("teapot");
    SimplifyOptions o;
    o.target.ratio = 0.2;
    o.morph = SimplifyTarget{.ratio = 0.05};
    Simplified a = simplify(teapot, o), b = simplify(teapot, o);
    ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
    ASSERT_EQ(a.mesh.indices, b.mesh.indices);
    EXPECT_EQ(std::memcmp(a.mesh.vertices.data(), b.mesh.vertices.data(), a.mesh.vertices.size() * sizeof(Vertex)), 0);
    EXPECT_EQ(std::memcmp(a.morph.data(), b.morph.data(), a.morph.size() * sizeof(MorphVertex)), 0);
}

TEST(Simplify, MorphTargetsLandOnTheCoarserMesh) {
    // The fine LOD's triangles, moved to their morph positions, are the coarse LOD's triangles
    // (same order, same vertex data) plus faces that collapsed to nothing.
    Mesh teapot = gen("teapot");
    SimplifyOptions o;
    o.target.ratio = 0.5;
    o.morph = SimplifyTarget{.ratio = 0.2};
    Simplified fine = simplify(teapot, o);
    Simplified coarse = to(teapot, 0.2);
    ASSERT_EQ(fine.morph.size(), fine.mesh.vertices.size());
    EXPECT_EQ(fine.stats.morph_triangles, coarse.stats.output_triangles);
    size_t next = 0, degenerate = 0;
    for (size_t t = 0; t < fine.mesh.indices.size(); t += 3) {
        const MorphVertex* m[3] = {&fine.morph[fine.mesh.indices[t]], &fine.morph[fine.mesh.indices[t + 1]], &fine.morph[fine.mesh.indices[t + 2]]};
        auto same = [](const MorphVertex* x, const MorphVertex* y) { return std::memcmp(x->position, y->position, 12) == 0; };
        if (same(m[0], m[1]) || same(m[1], m[2]) || same(m[0], m[2])) {
            ++degenerate;
            continue;
        }
        ASSERT_LT(next, coarse.mesh.indices.size());
        for (int c = 0; c < 3; ++c) {
            const Vertex& v = coarse.mesh.vertices[coarse.mesh.indices[next + c]];
            EXPECT_EQ(std::memcmp(m[c]->position, v.position, 12), 0);
            EXPECT_EQ(std::memcmp(m[c]->normal, v.normal, 12), 0);
            EXPECT_EQ(std::memcmp(m[c]->uv, v.uv, 8), 0);
        }
        next += 3;
    }
    EXPECT_EQ(next, coarse.mesh.indices.size());
    EXPECT_EQ(degenerate, fine.stats.output_triangles - coarse.stats.output_triangles);
}

TEST(Simplify, TeapotFigures) {
    // The figures of the note: time (printed only), triangle counts, geometric error.
    Mesh teapot = gen("teapot");
    const double size = extent(teapot);
    // Bounds: 1.25x the measured one-sided vertex Hausdorff distances (0.0049, 0.0091, 0.0246 on
    // a 2.5-unit diagonal). The computation is deterministic double arithmetic, so the margin
    // only has to absorb compilers. Placing vertices at endpoints/midpoints instead of the
    // quadric's optimum gives 0.0077, 0.0159, 0.0474 and fails; a sign error in the quadric
    // gives 0.09-0.14.
    const std::map<double, double> bound = {{0.5, 0.0062}, {0.25, 0.0115}, {0.1, 0.031}};
    for (double ratio : {0.5, 0.25, 0.1}) {
        // CPU time, not wall time: the figure should not depend on what else the machine runs.
        std::clock_t c0 = std::clock();
        Simplified s = to(teapot, ratio);
        double ms = 1000.0 * double(std::clock() - c0) / CLOCKS_PER_SEC;
        double out = vertex_distance(teapot, s.mesh), back = vertex_distance(s.mesh, teapot);
        std::printf("teapot ratio %.2f: %zu -> %zu triangles, %zu collapses (%zu re-costed, %zu refused), %.2f ms CPU; "
                    "max collapse error %.5f, vertex Hausdorff in->out %.5f out->in %.5f (extent %.3f)\n",
                    ratio, s.stats.input_triangles, s.stats.output_triangles, s.stats.collapses, s.stats.recosted,
                    s.stats.rejected, ms, s.stats.max_error, out, back, size);
        EXPECT_LT(std::max(out, back), bound.at(ratio)) << ratio;
    }
}
