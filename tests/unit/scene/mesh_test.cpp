#include "scene/camera.hpp"
#include "scene/mesh.hpp"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace pl::scene;

namespace {

glm::vec3 P(const Vertex& v) { return {v.position[0], v.position[1], v.position[2]}; }
glm::vec3 N(const Vertex& v) { return {v.normal[0], v.normal[1], v.normal[2]}; }

// Fraction of triangles whose geometric normal (CCW) agrees with the vertex normals.
double winding_agreement(const Mesh& m) {
    size_t ok = 0, n = 0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const Vertex &a = m.vertices[m.indices[t]], &b = m.vertices[m.indices[t + 1]], &c = m.vertices[m.indices[t + 2]];
        glm::vec3 g = glm::cross(P(b) - P(a), P(c) - P(a));
        if (glm::length(g) < 1e-9f) continue;
        ++n;
        ok += glm::dot(g, N(a) + N(b) + N(c)) > 0.0f;
    }
    return n ? double(ok) / double(n) : 0.0;
}

} // namespace

TEST(Mesh, GeneratorsAreWellFormed) {
    for (const auto& name : generator_names()) {
        auto m = generate_mesh(name, {});
        ASSERT_TRUE(m) << name;
        EXPECT_GT(m->indices.size(), 0u) << name;
        EXPECT_EQ(m->indices.size() % 3, 0u) << name;
        for (uint32_t i : m->indices) ASSERT_LT(i, m->vertices.size()) << name;
        for (const auto& v : m->vertices) {
            EXPECT_NEAR(glm::length(N(v)), 1.0f, 1e-4f) << name;
            glm::vec3 t(v.tangent[0], v.tangent[1], v.tangent[2]);
            EXPECT_NEAR(glm::length(t), 1.0f, 1e-3f) << name;
            EXPECT_NEAR(glm::dot(t, N(v)), 0.0f, 1e-3f) << name;
            EXPECT_TRUE(v.tangent[3] == 1.0f || v.tangent[3] == -1.0f) << name;
            EXPECT_GE(v.uv[0], 0.0f);
            EXPECT_LE(v.uv[0], 1.0f);
        }
        EXPECT_GT(winding_agreement(*m), 0.99) << name;
    }
}

TEST(Mesh, NormalsPointOutward) {
    for (const char* name : {"cube", "sphere", "torus"}) {
        auto m = generate_mesh(name, {});
        ASSERT_TRUE(m);
        for (const auto& v : m->vertices) {
            glm::vec3 p = P(v);
            if (std::string(name) == "torus") p -= glm::normalize(glm::vec3(p.x, 0, p.z)) * 0.7f;  // ring centre
            EXPECT_GT(glm::dot(N(v), p), 0.0f) << name;
        }
    }
    auto cube = generate_mesh("cube", {{"size", 2.0}});
    EXPECT_EQ(cube->vertices.size(), 24u);
    EXPECT_FLOAT_EQ(cube->bounds_max[0], 1.0f);
}

TEST(Mesh, BadArgumentsAreErrors) {
    auto a = generate_mesh("sphere", {{"segments", 2}});
    ASSERT_FALSE(a);
    EXPECT_NE(a.error().message.find("segments"), std::string::npos);
    auto b = generate_mesh("spehre", {});
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error().hint, "did you mean 'sphere'?");
    EXPECT_FALSE(generate_mesh("torus", {{"radius", -1}}));
}

TEST(Mesh, LoadsObjAndGltfAndRejectsGarbage) {
    auto dir = std::filesystem::temp_directory_path() / "passlab_mesh_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
    auto obj = load_mesh(dir / "tri.obj");
    ASSERT_TRUE(obj) << obj.error().format();
    EXPECT_EQ(obj->indices.size(), 3u);
    EXPECT_NEAR(obj->vertices[0].normal[2], 1.0f, 1e-5f);  // computed, CCW seen from +z
    // A triangle with an embedded base64 buffer: 3 float3 positions (36 bytes).
    std::ofstream(dir / "tri.gltf") << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
"bufferViews":[{"buffer":0,"byteLength":36}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}],"scene":0})";
    auto gl = load_mesh(dir / "tri.gltf");
    ASSERT_TRUE(gl) << gl.error().format();
    EXPECT_EQ(gl->vertices.size(), 3u);
    EXPECT_FLOAT_EQ(gl->vertices[1].position[0], 1.0f);
    std::ofstream(dir / "bad.obj") << "f 7 8 9\n";
    EXPECT_FALSE(load_mesh(dir / "bad.obj"));
    std::ofstream(dir / "bad.gltf") << "{ not json";
    EXPECT_FALSE(load_mesh(dir / "bad.gltf"));
    EXPECT_FALSE(load_mesh(dir / "missing.obj"));
    std::filesystem::remove_all(dir);
}

TEST(Camera, Conventions) {
    OrbitCamera c;
    c.yaw_deg = 0;
    c.pitch_deg = 0;
    c.distance = 3;
    glm::vec3 p = c.position();
    EXPECT_NEAR(p.z, 3.0f, 1e-5f);
    glm::mat4 vp = c.projection(1.0f) * c.view();
    glm::vec4 centre = vp * glm::vec4(0, 0, 0, 1);
    EXPECT_NEAR(centre.x / centre.w, 0.0f, 1e-5f);
    EXPECT_NEAR(centre.y / centre.w, 0.0f, 1e-5f);
    EXPECT_GT(centre.z / centre.w, 0.0f);
    EXPECT_LT(centre.z / centre.w, 1.0f);
    // World +Y appears towards the top of the image: Vulkan NDC y is negative at the top.
    glm::vec4 up = vp * glm::vec4(0, 0.5f, 0, 1);
    EXPECT_LT(up.y / up.w, 0.0f);
    glm::vec4 right = vp * glm::vec4(0.5f, 0, 0, 1);
    EXPECT_GT(right.x / right.w, 0.0f);
}

// A face of 200,000 corners hung tinyobjloader's triangulation (quadratic); with the host's own
// (a linear fan) it is refused at once, since the reader counts corners in a byte; a face of
// 200 corners is fanned. Quads still split along the shorter diagonal.
TEST(ObjLoad, LargeFacesAreFannedOrRefusedNotHung) {
    auto dir = std::filesystem::temp_directory_path() / "passlab_obj_huge_face";
    std::filesystem::create_directories(dir);
    auto polygon = [&](const std::string& name, int n) {
        std::ofstream f(dir / name);
        for (int i = 0; i < n; ++i) {
            double a = 6.283185307179586 * i / n;
            f << "v " << std::cos(a) << " " << std::sin(a) << " 0\n";
        }
        f << "f";
        for (int i = 1; i <= n; ++i) f << " " << i;
        f << "\n";
    };
    polygon("huge.obj", 200000);
    auto t0 = std::chrono::steady_clock::now();
    auto m = load_mesh(dir / "huge.obj");
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_FALSE(m);
    EXPECT_NE(m.error().message.find("256 or more corners"), std::string::npos) << m.error().format();
    EXPECT_LT(s, 20.0);  // a hang guard, not a timing test
    polygon("200.obj", 200);
    auto p = load_mesh(dir / "200.obj");
    ASSERT_TRUE(p) << p.error().format();
    EXPECT_EQ(p->indices.size(), size_t(3) * 198);
    {
        std::ofstream f(dir / "quad.obj");
        // The diagonal 0-2 is shorter than 1-3: triangles (0,1,2), (0,2,3).
        f << "v 0 0 0\nv 4 0 0\nv 1 1 0\nv 0 4 0\nf 1 2 3 4\n";
    }
    auto q = load_mesh(dir / "quad.obj");
    ASSERT_TRUE(q) << q.error().format();
    ASSERT_EQ(q->indices.size(), 6u);
    EXPECT_FLOAT_EQ(P(q->vertices[q->indices[3]]).x, 0.0f);
    EXPECT_FLOAT_EQ(P(q->vertices[q->indices[4]]).x, 1.0f);  // corner 2 (1, 1) starts the second
    std::filesystem::remove_all(dir);
}
