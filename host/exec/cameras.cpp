#include "exec/cameras.hpp"

#include "scene/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pl::exec {

namespace {
glm::vec3 vec3(const std::array<double, 3>& a) {
    return {static_cast<float>(a[0]), static_cast<float>(a[1]), static_cast<float>(a[2])};
}
} // namespace

CameraBlock camera_block(const graph::CameraValues& v, int face) {
    CameraBlock c{};
    const float near = static_cast<float>(v.near), far = static_cast<float>(v.far), aspect = static_cast<float>(v.aspect);
    const glm::vec3 eye = vec3(v.eye);
    if (v.cube) {
        c.view = scene::cube_face_view(eye, face);
        c.proj = scene::perspective(glm::radians(90.0f), 1.0f, near, far, false);
    } else {
        c.view = scene::look_at(eye, vec3(v.target), vec3(v.up));
        c.proj = v.ortho ? scene::orthographic(static_cast<float>(v.ortho_height), aspect, near, far)
                         : scene::perspective(glm::radians(static_cast<float>(v.fov)), aspect, near, far);
    }
    c.view_proj = c.proj * c.view;
    c.inv_view = glm::inverse(c.view);
    c.inv_proj = glm::inverse(c.proj);
    c.inv_view_proj = glm::inverse(c.view_proj);
    c.position = glm::vec4(eye, 1.0f);
    c.clip = {near, far, v.cube ? 1.0f : aspect, v.ortho ? 1.0f : 0.0f};
    return c;
}

Result<CameraEntries> eval_cameras(const std::vector<graph::CameraDesc>& cameras, const graph::SizeEnv& env) {
    CameraEntries out;
    for (const auto& c : cameras) {
        auto v = graph::eval_camera(c, env);
        if (!v) return v.error();
        out.first.push_back(static_cast<int>(out.entries.size()));
        for (int f = 0; f < c.faces(); ++f) out.entries.push_back(camera_block(*v, f));
    }
    return out;
}

void apply_camera(FrameBlock& fb, const CameraBlock& c, const glm::mat4& prev_view_proj) {
    fb.view = c.view;
    fb.proj = c.proj;
    fb.view_proj = c.view_proj;
    fb.inv_view = c.inv_view;
    fb.inv_proj = c.inv_proj;
    fb.inv_view_proj = c.inv_view_proj;
    fb.prev_view_proj = prev_view_proj;
    fb.camera_pos = c.position;
    fb.jitter = glm::vec4(0.0f);
    fb.aspect = c.clip.z;
}

bool renders_cube_faces(const graph::GraphDesc& g, const graph::PassDesc& pd) {
    const graph::CameraDesc* c = pd.camera.empty() ? nullptr : g.find_camera(pd.camera);
    return c && c->cube;
}

} // namespace pl::exec
