// The BVH build's invariants (scene/bvh.hpp) and the packed scene buffer (scene/scene_buffer.hpp).
#include "scene/bvh.hpp"
#include "scene/mesh.hpp"
#include "scene/scene_buffer.hpp"
#include "scene/scene_gpu.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>

using namespace pl::scene;

namespace {

std::vector<TrianglePositions> teapot_triangles() {
    auto m = generate_mesh("teapot", {});
    EXPECT_TRUE(m.ok());
    return mesh_triangles(*m);
}

bool inside(const Aabb& inner, const Aabb& outer) {
    return glm::all(glm::greaterThanEqual(inner.lo, outer.lo)) && glm::all(glm::lessThanEqual(inner.hi, outer.hi));
}

// Every structural invariant, checked against an independent recursive reading of the preorder
// layout (first child = i + 1, second child = the first child's skip).
void check_invariants(const std::vector<TrianglePositions>& tris, const Bvh& bvh, int leaf_size) {
    ASSERT_FALSE(bvh.nodes.empty());
    std::vector<int> seen(tris.size(), 0);
    std::function<uint32_t(uint32_t)> walk = [&](uint32_t i) -> uint32_t {
        const BvhNode& n = bvh.nodes.at(i);
        uint32_t size = 1;
        if (n.count > 0) {
            EXPECT_LE(n.count, uint32_t(leaf_size)) << "node " << i;
            Aabb exact;
            for (uint32_t k = n.first; k < n.first + n.count; ++k) {
                uint32_t t = bvh.triangles.at(k);
                ++seen.at(t);
                for (const auto& p : tris[t]) exact.grow(p);
            }
            EXPECT_EQ(exact.lo, n.box.lo) << "leaf " << i << " box is not its triangles' bounds";
            EXPECT_EQ(exact.hi, n.box.hi) << "leaf " << i;
        } else {
            uint32_t left = i + 1, right = bvh.nodes.at(left).skip;
            EXPECT_TRUE(inside(bvh.nodes.at(left).box, n.box)) << "node " << i;
            EXPECT_TRUE(inside(bvh.nodes.at(right).box, n.box)) << "node " << i;
            size += walk(left);
            size += walk(right);
        }
        EXPECT_EQ(n.skip, i + size) << "node " << i << ": skip must be index + subtree size";
        return size;
    };
    EXPECT_EQ(walk(0), bvh.nodes.size()) << "the root's subtree is the whole tree";
    for (size_t t = 0; t < tris.size(); ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t << " must be in exactly one leaf";
    EXPECT_EQ(bvh.triangles.size(), tris.size());
}

Aabb bounds(const std::vector<TrianglePositions>& tris) {
    Aabb b;
    for (const auto& t : tris)
        for (const auto& p : t) b.grow(p);
    return b;
}

} // namespace

TEST(Bvh, TeapotInvariants) {
    auto tris = teapot_triangles();
    ASSERT_EQ(tris.size(), 4096u);
    for (int leaf : {1, 4, 15}) {
        Bvh bvh = build_bvh(tris, leaf);
        check_invariants(tris, bvh, leaf);
        EXPECT_EQ(bvh.nodes[0].box.lo, bounds(tris).lo) << "root bounds = mesh bounds";
        EXPECT_EQ(bvh.nodes[0].box.hi, bounds(tris).hi);
    }
}

TEST(Bvh, RootBoundsAreTheMeshBounds) {
    auto m = generate_mesh("teapot", {});
    ASSERT_TRUE(m.ok());
    compute_bounds(*m);  // over the vertices; the teapot references each of them
    Bvh bvh = build_bvh(mesh_triangles(*m), 4);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(bvh.nodes[0].box.lo[k], m->bounds_min[k]);
        EXPECT_EQ(bvh.nodes[0].box.hi[k], m->bounds_max[k]);
    }
}

TEST(Bvh, SahTreeIsShallowAndCheap) {
    // A sanity bound on quality, not a golden: a balanced tree over 4096 triangles in leaves of
    // 4 has depth 10; SAH trees are deeper but not degenerate.
    auto tris = teapot_triangles();
    Bvh bvh = build_bvh(tris, 4);
    std::function<int(uint32_t)> depth = [&](uint32_t i) -> int {
        if (bvh.nodes[i].count) return 1;
        return 1 + std::max(depth(i + 1), depth(bvh.nodes[i + 1].skip));
    };
    EXPECT_LT(depth(0), 32);
    // A full binary tree: 2 * leaves - 1 nodes, so leaves hold about two triangles on average
    // (with traversal and intersection costed equally, the SAH splits most 4-triangle nodes).
    size_t leaves = 0;
    for (const auto& n : bvh.nodes) leaves += n.count > 0;
    EXPECT_EQ(bvh.nodes.size(), 2 * leaves - 1);
}

TEST(Bvh, Deterministic) {
    auto tris = teapot_triangles();
    Bvh a = build_bvh(tris, 4), b = build_bvh(std::vector<TrianglePositions>(tris), 4);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)));
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(Bvh, OneTriangle) {
    std::vector<TrianglePositions> tris = {{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}};
    Bvh bvh = build_bvh(tris, 4);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].count, 1u);
    EXPECT_EQ(bvh.nodes[0].skip, 1u);
    check_invariants(tris, bvh, 4);
}

TEST(Bvh, EmptyInput) {
    Bvh bvh = build_bvh({}, 4);
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.triangles.empty());
}

TEST(Bvh, IdenticalCentroidsStillRespectTheLeafBound) {
    // 1000 copies of one triangle: every split costs the same; the build must still split (by
    // index, balanced) down to leaves of at most leaf_size.
    std::vector<TrianglePositions> tris(1000, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
    Bvh bvh = build_bvh(tris, 4);
    check_invariants(tris, bvh, 4);
    std::function<int(uint32_t)> depth = [&](uint32_t i) -> int {
        if (bvh.nodes[i].count) return 1;
        return 1 + std::max(depth(i + 1), depth(bvh.nodes[i + 1].skip));
    };
    EXPECT_LE(depth(0), 10);  // balanced: ceil(log2(1000 / 4)) + 1 = 9
}

TEST(Bvh, CoplanarTriangles) {
    auto m = generate_mesh("plane", {{"segments", 16.0}});
    ASSERT_TRUE(m.ok());
    auto tris = mesh_triangles(*m);
    Bvh bvh = build_bvh(tris, 2);
    check_invariants(tris, bvh, 2);
    EXPECT_EQ(bvh.nodes[0].box.lo.y, 0.0f);
    EXPECT_EQ(bvh.nodes[0].box.hi.y, 0.0f);  // a flat root box
}

TEST(Bvh, ZeroAreaTriangles) {
    // Points (three equal corners) and segments (collinear corners), mixed with real ones.
    std::vector<TrianglePositions> tris;
    for (int i = 0; i < 50; ++i) {
        glm::vec3 p(float(i % 7), float(i % 3), 0.5f * float(i));
        tris.push_back({p, p, p});
        tris.push_back({p, p + glm::vec3(1, 0, 0), p + glm::vec3(2, 0, 0)});
        tris.push_back({p, p + glm::vec3(1, 0, 0), p + glm::vec3(0, 1, 0)});
    }
    Bvh bvh = build_bvh(tris, 3);
    check_invariants(tris, bvh, 3);
    std::vector<TrianglePositions> points(20, {glm::vec3(1, 2, 3), glm::vec3(1, 2, 3), glm::vec3(1, 2, 3)});
    Bvh dots = build_bvh(points, 1);
    check_invariants(points, dots, 1);
    EXPECT_EQ(dots.nodes.size(), 39u);  // a full binary tree with 20 leaves
}

namespace {

Mesh one_triangle_mesh(float x) {
    Mesh m;
    m.vertices = {{{x, 0, 0}, {}, {}, {}}, {{x + 1, 0, 0}, {}, {}, {}}, {{x, 1, 0}, {}, {}, {}}};
    m.indices = {0, 1, 2};
    return m;
}

gpu::SceneHeader header_of(const std::vector<uint32_t>& w) {
    gpu::SceneHeader h;
    std::memcpy(&h, w.data(), sizeof h);
    return h;
}

template <class T> T record(const std::vector<uint32_t>& w, uint32_t at) {
    T t;
    std::memcpy(&t, w.data() + sizeof(gpu::SceneHeader) / 4 + size_t(at) * 4, sizeof t);
    return t;
}

} // namespace

TEST(SceneBuffer, LayoutOfTwoMeshes) {
    auto teapot = generate_mesh("teapot", {{"subdivisions", 2.0}});
    ASSERT_TRUE(teapot.ok());
    Mesh tri = one_triangle_mesh(5);
    auto words = build_scene_buffer({{"teapot", &*teapot}, {"tri", &tri}}, true, 4);
    ASSERT_TRUE(words.ok()) << words.error().format();
    gpu::SceneHeader h = header_of(*words);
    EXPECT_EQ(h.mesh_count, 2u);
    EXPECT_EQ(h.triangle_count, 32u * 2 * 2 * 2 + 1);
    EXPECT_EQ(h.leaf_size, 4u);
    EXPECT_EQ(h.nodes_at, 2u);
    EXPECT_EQ(h.triangles_at, h.nodes_at + 2 * h.node_count);
    EXPECT_EQ(h.record_count, h.triangles_at + 3 * h.triangle_count);
    EXPECT_EQ(words->size() * 4, sizeof h + h.record_count * 16);

    auto m0 = record<gpu::SceneMesh>(*words, 0), m1 = record<gpu::SceneMesh>(*words, 1);
    EXPECT_EQ(m0.node_offset, 0u);
    EXPECT_EQ(m1.node_offset, m0.node_count);  // contiguous per mesh
    EXPECT_EQ(m1.node_count, 1u);
    EXPECT_EQ(m0.triangle_offset, 0u);
    EXPECT_EQ(m1.triangle_offset, m0.triangle_count);
    EXPECT_EQ(m0.node_count + m1.node_count, h.node_count);

    // Skip indices are global; a mesh's root skips past exactly its own nodes; leaves decode to
    // ranges inside their mesh's triangles, whose records name the mesh.
    for (auto m : {m0, m1}) {
        auto root = record<gpu::BvhNode>(*words, h.nodes_at + 2 * m.node_offset);
        EXPECT_EQ(root.skip, m.node_offset + m.node_count);
        for (uint32_t i = m.node_offset; i < m.node_offset + m.node_count; ++i) {
            auto n = record<gpu::BvhNode>(*words, h.nodes_at + 2 * i);
            if (!n.leaf) continue;
            uint32_t first = n.leaf >> gpu::kLeafCountBits, count = n.leaf & ((1u << gpu::kLeafCountBits) - 1);
            EXPECT_GE(count, 1u);
            EXPECT_LE(count, 4u);
            EXPECT_GE(first, m.triangle_offset);
            EXPECT_LE(first + count, m.triangle_offset + m.triangle_count);
            EXPECT_EQ(n.skip, i + 1);
        }
    }
    auto last = record<gpu::SceneTriangle>(*words, h.triangles_at + 3 * (h.triangle_count - 1));
    EXPECT_EQ(last.mesh, 1u);
    EXPECT_EQ(last.prim, 0u);
    EXPECT_EQ(last.v0[0], 5.0f);
}

TEST(SceneBuffer, TrianglesGeneratorHoldsTheSameRecordsWithoutNodes) {
    auto teapot = generate_mesh("teapot", {{"subdivisions", 3.0}});
    ASSERT_TRUE(teapot.ok());
    auto bvh = build_scene_buffer({{"teapot", &*teapot}}, true, 4);
    auto flat = build_scene_buffer({{"teapot", &*teapot}}, false, 4);
    ASSERT_TRUE(bvh.ok() && flat.ok());
    gpu::SceneHeader hb = header_of(*bvh), hf = header_of(*flat);
    EXPECT_EQ(hf.node_count, 0u);
    EXPECT_EQ(hf.leaf_size, 0u);
    EXPECT_EQ(hf.triangle_count, hb.triangle_count);
    EXPECT_EQ(hf.triangles_at, hf.nodes_at);
    // Flat records are in index-list order; the BVH's are a permutation of them.
    std::vector<int> found(hf.triangle_count, 0);
    for (uint32_t j = 0; j < hf.triangle_count; ++j) {
        auto f = record<gpu::SceneTriangle>(*flat, hf.triangles_at + 3 * j);
        EXPECT_EQ(f.prim, j);
        auto b = record<gpu::SceneTriangle>(*bvh, hb.triangles_at + 3 * j);
        auto same = record<gpu::SceneTriangle>(*flat, hf.triangles_at + 3 * b.prim);
        EXPECT_EQ(0, std::memcmp(&b, &same, sizeof b));
        ++found.at(b.prim);
    }
    for (int n : found) EXPECT_EQ(n, 1);
}

TEST(SceneBuffer, ByteIdenticalRebuilds) {
    auto a = generate_mesh("teapot", {}), b = generate_mesh("teapot", {});
    Mesh floor = one_triangle_mesh(0);
    auto wa = build_scene_buffer({{"teapot", &*a}, {"floor", &floor}}, true, 4);
    auto wb = build_scene_buffer({{"teapot", &*b}, {"floor", &floor}}, true, 4);
    ASSERT_TRUE(wa.ok() && wb.ok());
    EXPECT_EQ(*wa, *wb);
}

TEST(SceneBuffer, RefusesNonFinitePositionsAndBadIndices) {
    Mesh m = one_triangle_mesh(0);
    m.vertices[1].position[2] = std::numeric_limits<float>::quiet_NaN();
    auto r = build_scene_buffer({{"bad", &m}}, true, 4);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("mesh 'bad': vertex 1 has a non-finite position"), std::string::npos) << r.error().message;
    Mesh k = one_triangle_mesh(0);
    k.indices[2] = 7;
    auto s = build_scene_buffer({{"k", &k}}, false, 4);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("index 2 refers to vertex 7 of 3"), std::string::npos) << s.error().message;
}

TEST(SceneBuffer, EmptyMeshHasAnEmptyRange) {
    Mesh empty;
    Mesh tri = one_triangle_mesh(0);
    auto w = build_scene_buffer({{"empty", &empty}, {"tri", &tri}}, true, 4);
    ASSERT_TRUE(w.ok());
    auto m0 = record<gpu::SceneMesh>(*w, 0);
    EXPECT_EQ(m0.node_count, 0u);
    EXPECT_EQ(m0.triangle_count, 0u);
}
