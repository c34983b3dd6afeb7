// Orbit camera: yaw/pitch/distance around a target, producing view and projection matrices in
// Vulkan conventions (right-handed world, y down in clip space is corrected, depth 0..1).
#pragma once

#include <glm/glm.hpp>

namespace pl::scene {

struct OrbitCamera {
    glm::vec3 target{0.0f};
    float distance = 3.0f;
    float yaw_deg = 30.0f;    // around +Y, 0 looks along -Z
    float pitch_deg = 20.0f;  // positive looks down at the target
    float fov_deg = 45.0f;
    float near = 0.05f, far = 100.0f;
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
