#include "scene/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace pl::scene {

glm::mat4 perspective(float fov_rad, float aspect, float near, float far, bool flip_y) {
    glm::mat4 p = std::isinf(far) ? glm::mat4(0.0f) : glm::perspective(fov_rad, aspect, near, far);
    if (std::isinf(far)) {
        // glm::perspective (right-handed, depth 0..1) in the limit far -> inf: z_clip = -z - near,
        // w_clip = -z, so depth = 1 - near / distance; with w = 0 input, z_clip == w_clip exactly.
        const float f = 1.0f / std::tan(0.5f * fov_rad);
        p[0][0] = f / aspect;
        p[1][1] = f;
        p[2][2] = -1.0f;
        p[2][3] = -1.0f;
        p[3][2] = -near;
    }
    // Vulkan's clip space has y pointing down: flip so world +Y is up on screen. With the flip,
    // counter-clockwise triangles (seen from outside) stay counter-clockwise in framebuffer space.
    if (flip_y) p[1][1] *= -1.0f;
    return p;
}

glm::mat4 orthographic(float height, float aspect, float near, float far) {
    glm::mat4 p = glm::ortho(-0.5f * height * aspect, 0.5f * height * aspect, -0.5f * height, 0.5f * height, near, far);
    p[1][1] *= -1.0f;
    return p;
}

glm::mat4 look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    glm::vec3 f = glm::normalize(target - eye);
    if (glm::length(glm::cross(f, glm::normalize(up))) < 1e-6f) up = f.y < 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1);
    return glm::lookAt(eye, target, up);
}

glm::vec3 cube_face_direction(int face) {
    static const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    return dirs[std::clamp(face, 0, 5)];
}

glm::mat4 cube_face_view(glm::vec3 eye, int face) {
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAt(eye, eye + cube_face_direction(face), ups[std::clamp(face, 0, 5)]);
}

glm::vec3 OrbitCamera::position() const {
    float yaw = glm::radians(yaw_deg), pitch = glm::radians(pitch_deg);
    // yaw 0, pitch 0: on +Z looking at the target along -Z; positive pitch lifts the camera.
    glm::vec3 dir(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return target + distance * dir;
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(position(), target, glm::vec3(0, 1, 0)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
    return ortho ? orthographic(ortho_height, aspect, near, far) : perspective(glm::radians(fov_deg), aspect, near, far);
}

void OrbitCamera::rotate(float dyaw, float dpitch) {
    yaw_deg += dyaw;
    pitch_deg = std::clamp(pitch_deg + dpitch, -89.0f, 89.0f);
}

void OrbitCamera::zoom(float factor) { distance = std::clamp(distance * factor, 0.01f, 1e4f); }

} // namespace pl::scene
