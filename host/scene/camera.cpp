#include "scene/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace pl::scene {

glm::vec3 OrbitCamera::position() const {
    float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
    // yaw 0, pitch 0: on +Z looking at the target along -Z; positive pitch lifts the camera.
    glm::vec3 dir(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return target + distance * dir;
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(position(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
    glm::mat4 p = ortho ? glm::ortho(-0.5f * ortho_height * aspect, 0.5f * ortho_height * aspect, -0.5f * ortho_height,
                                     0.5f * ortho_height, near, far)
                        : glm::perspective(glm::radians(fov_deg), aspect, near, far);
    // Vulkan's clip space has y pointing down: flip so world +Y is up on screen. With the flip,
    // counter-clockwise triangles (seen from outside) stay counter-clockwise in framebuffer space.
    p[1][1] *= -1.0f;
    return p;
}

void OrbitCamera::rotate(float dyaw, float dpitch) {
    yaw_deg += dyaw;
    pitch_deg = std::clamp(pitch_deg + dpitch, -89.0f, 89.0f);
}

void OrbitCamera::zoom(float factor) { distance = std::clamp(distance * factor, 0.01f, 1e4f); }

} // namespace pl::scene
