// Camera math: cube faces agree with the Vulkan spec's face selection table, the infinite
// projection is the limit of the finite one and puts points at infinity on depth 1, and a look-at
// whose up is parallel to the view direction stays finite.
#include "scene/camera.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace pl::scene;

namespace {

// Vulkan spec "Cube Map Face Selection and Transformations": for direction r, the face, and the
// (sc, tc, ma) that give s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2.
struct Face {
    int face;
    float s, t;
};
Face spec_face(glm::vec3 r) {
    glm::vec3 a = glm::abs(r);
    float sc, tc, ma;
    int face;
    if (a.x >= a.y && a.x >= a.z) face = r.x > 0 ? 0 : 1, sc = r.x > 0 ? -r.z : r.z, tc = -r.y, ma = a.x;
    else if (a.y >= a.z) face = r.y > 0 ? 2 : 3, sc = r.x, tc = r.y > 0 ? r.z : -r.z, ma = a.y;
    else face = r.z > 0 ? 4 : 5, sc = r.z > 0 ? r.x : -r.x, tc = -r.y, ma = a.z;
    return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}

} // namespace

TEST(Camera, CubeFacesMatchTheSpecsFaceSelection) {
    // The face's view-projection maps direction r to ndc = (s, t) * 2 - 1; framebuffer row 0 is
    // ndc y = -1 and t = 0 is the first row, so the texel rendered is the texel sampled.
    const glm::vec3 eye(0.5f, -1.0f, 2.0f);
    const glm::mat4 proj = perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f, false);
    const glm::vec3 dirs[] = {{1, 0.5f, 0.25f},  {-1, -0.3f, 0.6f}, {0.2f, 1, -0.4f}, {-0.7f, -1, 0.1f},
                              {0.3f, 0.6f, 1},   {-0.1f, 0.2f, -1}, {1, -0.9f, 0.8f}, {0.9f, 0.95f, -1}};
    for (glm::vec3 r : dirs) {
        Face f = spec_face(r);
        glm::vec4 clip = proj * cube_face_view(eye, f.face) * glm::vec4(eye + 3.0f * r, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        EXPECT_NEAR(clip.x / clip.w, f.s * 2 - 1, 1e-5f) << "face " << f.face;
        EXPECT_NEAR(clip.y / clip.w, f.t * 2 - 1, 1e-5f) << "face " << f.face;
        EXPECT_EQ(glm::dot(cube_face_direction(f.face), r), std::max({std::fabs(r.x), std::fabs(r.y), std::fabs(r.z)}));
    }
}

TEST(Camera, InfinitePerspectiveIsTheLimitAndKeepsInfinityOnDepthOne) {
    const float fov = glm::radians(60.0f), aspect = 1.5f, n = 0.1f;
    glm::mat4 inf = perspective(fov, aspect, n, INFINITY);
    glm::mat4 far = perspective(fov, aspect, n, 1e7f);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            EXPECT_TRUE(std::isfinite(inf[c][r]));
            EXPECT_NEAR(inf[c][r], far[c][r], 1e-5f * std::max(1.0f, std::fabs(far[c][r])));
        }
    // depth = 1 - near / distance; the near plane at 0.
    glm::vec4 p = inf * glm::vec4(0, 0, -4, 1);
    EXPECT_NEAR(p.z / p.w, 1 - n / 4, 1e-6f);
    p = inf * glm::vec4(0, 0, -n, 1);
    EXPECT_NEAR(p.z / p.w, 0.0f, 1e-6f);
    // A direction (w = 0) through any view: z == w exactly, inside the clip volume.
    glm::mat4 vp = inf * glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(0.3f, -0.2f, 0.1f), glm::vec3(0, 1, 0));
    for (glm::vec3 d : {glm::vec3(-0.7f, -0.6f, -0.7f), glm::vec3(-1, -2, -3), glm::vec3(-0.2f, -0.5f, -0.9f)}) {
        glm::vec4 c = vp * glm::vec4(d, 0);
        EXPECT_GT(c.w, 0.0f);
        EXPECT_EQ(c.z, c.w);
    }
    // y is flipped like the finite projection (world +Y up on screen).
    EXPECT_LT(inf[1][1], 0.0f);
}

TEST(Camera, LookAtWithParallelUpStaysFinite) {
    for (glm::vec3 eye : {glm::vec3(0, 10, 0), glm::vec3(0, -10, 0)}) {
        glm::mat4 v = look_at(eye, glm::vec3(0), glm::vec3(0, 1, 0));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(v[c][r]));
        // Still looks at the target: the origin is straight ahead, 10 away.
        glm::vec4 o = v * glm::vec4(0, 0, 0, 1);
        EXPECT_NEAR(o.x, 0.0f, 1e-6f);
        EXPECT_NEAR(o.y, 0.0f, 1e-6f);
        EXPECT_NEAR(o.z, -10.0f, 1e-5f);
    }
    // Looking down, the fallback up is -Z: world -Z is up in the image (view y > 0).
    glm::mat4 v = look_at(glm::vec3(0, 10, 0), glm::vec3(0), glm::vec3(0, 1, 0));
    EXPECT_GT((v * glm::vec4(0, 0, -1, 1)).y, 0.0f);
}

TEST(Camera, OrbitProjectionUnchangedForFiniteFar) {
    OrbitCamera c;
    glm::mat4 expect = glm::perspective(glm::radians(c.fov_deg), 1.5f, c.near, c.far);
    expect[1][1] *= -1.0f;
    EXPECT_EQ(c.projection(1.5f), expect);
}
