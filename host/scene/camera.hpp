// Cameras in Vulkan conventions (right-handed world, depth 0..1, clip-space y flipped so world
// +Y is up on screen): the orbit camera of [view], and the projection and view helpers that the
// named cameras of [cameras] are built from (infinite far plane, cube-map faces).
#pragma once

#include <glm/glm.hpp>

namespace pl::scene {

// Perspective projection, y flipped (flip_y = false: unflipped, as cube faces need). far = +inf
// gives the infinite projection: depth = 1 - near / distance, so depth -> 1 far away and a point
// at infinity (w = 0, e.g. a shadow volume's extruded dark cap) lands exactly on depth 1 (clip
// z == w), inside the clip volume, instead of the NaNs of a finite formula with far = inf.
glm::mat4 perspective(float fov_rad, float aspect, float near, float far, bool flip_y = true);
// Orthographic projection of a volume `height` tall and `height * aspect` wide, y flipped.
glm::mat4 orthographic(float height, float aspect, float near, float far);
// glm::lookAt, except that an `up` parallel to the view direction (a light straight above its
// target with up = +Y) is replaced by -Z (looking down) or +Z (looking up) instead of giving NaNs.
glm::mat4 look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up);

// Cube-map face i (0..5 = +X, -X, +Y, -Y, +Z, -Z, Vulkan's layer order): the view from `eye`
// along the face's axis with the face's up vector (+X, -X, +Z, -Z: up -Y; +Y: up +Z; -Y: up -Z),
// which with perspective(90 degrees, 1, near, far, flip_y = false) renders texel (s, t) of the
// face where a samplerCube lookup finds it (Vulkan spec, "Cube Map Face Selection": e.g. +X has
// s along -Z and t along -Y). That image is a mirror of the scene, so triangles' winding flips:
// draws through a cube camera get the opposite front face (exec/pipelines.cpp).
glm::mat4 cube_face_view(glm::vec3 eye, int face);
glm::vec3 cube_face_direction(int face);

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 3.0f;
    float yaw_deg = 30.0f;    // around +Y, 0 looks along -Z
    float pitch_deg = 20.0f;  // positive looks down at the target
    float fov_deg = 45.0f;
    float near = 0.05f, far = 100.0f;  // far may be +inf (infinite perspective)
    bool ortho = false;
    float ortho_height = 2.0f;

    glm::vec3 position() const;
    glm::mat4 view() const;
    // Projection for Vulkan clip space: y flipped so +Y is up on screen, depth in [0,1].
    glm::mat4 projection(float aspect) const;

    // Mouse interaction for the live lab: drag rotates, wheel zooms.
    void rotate(float dyaw_deg, float dpitch_deg);
    void zoom(float factor);
};

} // namespace pl::scene
