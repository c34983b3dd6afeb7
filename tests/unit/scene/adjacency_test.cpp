// Adjacency index lists for geometry shaders: every edge of a closed mesh finds the triangle
// across it (through the seams where generators duplicate vertices), open borders point back
// at their own triangle.
#include "scene/mesh.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

using namespace pl::scene;

namespace {
glm::vec3 P(const Mesh& m, uint32_t i) { return {m.vertices[i].position[0], m.vertices[i].position[1], m.vertices[i].position[2]}; }
bool same(glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-5f; }

// For triangle t and edge e of an adjacency list: is the adjacent vertex the triangle's own
// opposite vertex (by position)?
bool points_back(const Mesh& m, const std::vector<uint32_t>& adj, size_t t, int e) {
    uint32_t opposite = adj[t * 6 + ((e + 2) % 3) * 2];
    return same(P(m, adj[t * 6 + e * 2 + 1]), P(m, opposite));
}
} // namespace

TEST(Adjacency, ClosedMeshesHaveANeighbourAcrossEveryEdge) {
    for (const char* g : {"cube", "sphere", "torus"}) {
        auto m = generate_mesh(g, {});
        ASSERT_TRUE(m) << g;
        auto adj = adjacency_indices(*m);
        ASSERT_EQ(adj.size(), m->indices.size() * 2) << g;
        size_t tris = m->indices.size() / 3, back = 0;
        for (size_t t = 0; t < tris; ++t) {
            glm::vec3 a = P(*m, m->indices[t * 3]), b = P(*m, m->indices[t * 3 + 1]), c = P(*m, m->indices[t * 3 + 2]);
            if (same(a, b) || same(b, c) || same(a, c)) continue;  // zero-area pole triangles
            for (int e = 0; e < 3; ++e) {
                EXPECT_EQ(adj[t * 6 + e * 2], m->indices[t * 3 + e]);  // the triangle itself, unchanged
                back += points_back(*m, adj, t, e);
            }
        }
        // Closed: no edge of a triangle with area may point back.
        EXPECT_EQ(back, 0u) << g;
    }
}

TEST(Adjacency, NeighbourSharesTheEdge) {
    auto m = generate_mesh("sphere", {{"segments", 8}, {"rings", 4}});
    ASSERT_TRUE(m);
    auto adj = adjacency_indices(*m);
    // The triangle across edge (a, b) contains a, b and the adjacent vertex: find it.
    size_t tris = m->indices.size() / 3;
    for (size_t t = 0; t < tris; ++t)
        for (int e = 0; e < 3; ++e) {
            glm::vec3 t0 = P(*m, m->indices[t * 3]), t1 = P(*m, m->indices[t * 3 + 1]), t2 = P(*m, m->indices[t * 3 + 2]);
            if (same(t0, t1) || same(t1, t2) || same(t0, t2)) continue;
            glm::vec3 a = P(*m, m->indices[t * 3 + e]), b = P(*m, m->indices[t * 3 + (e + 1) % 3]), c = P(*m, adj[t * 6 + e * 2 + 1]);
            bool found = false;
            for (size_t u = 0; u < tris && !found; ++u) {
                if (u == t) continue;
                glm::vec3 q[3] = {P(*m, m->indices[u * 3]), P(*m, m->indices[u * 3 + 1]), P(*m, m->indices[u * 3 + 2])};
                auto has = [&](glm::vec3 v) { return same(v, q[0]) || same(v, q[1]) || same(v, q[2]); };
                found = has(a) && has(b) && has(c);
            }
            EXPECT_TRUE(found) << "triangle " << t << " edge " << e;
        }
}

TEST(Adjacency, OpenBorderPointsBack) {
    auto m = generate_mesh("plane", {{"segments", 2}});
    ASSERT_TRUE(m);
    auto adj = adjacency_indices(*m);
    size_t tris = m->indices.size() / 3, back = 0;
    for (size_t t = 0; t < tris; ++t)
        for (int e = 0; e < 3; ++e) back += points_back(*m, adj, t, e);
    // A 2x2 grid of quads, 8 triangles: 8 border edges (2 per side), the 16 others inside.
    EXPECT_EQ(back, 8u);
}
