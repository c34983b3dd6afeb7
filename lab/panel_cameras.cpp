// The panel's Cameras section: every named camera as the last frame saw it (its params may move
// it), with the values a shader reads from cameras.NAME and its frustum's corners in world space,
// plus frame.accum_frame (how long a progressive render has been accumulating).
#include "panel.hpp"

#include <imgui.h>

#include <cmath>

namespace pl::lab {

namespace {

void matrix_rows(const char* label, const glm::mat4& m) {
    if (!ImGui::TreeNode(label)) return;
    for (int r = 0; r < 4; ++r) ImGui::Text("%9.4f %9.4f %9.4f %9.4f", m[0][r], m[1][r], m[2][r], m[3][r]);  // row r
    ImGui::TreePop();
}

void camera_entry(const char* label, const exec::CameraBlock& c) {
    if (!ImGui::TreeNode(label)) return;
    const glm::vec3 eye(c.position), forward = -glm::vec3(c.inv_view[2]), up = glm::vec3(c.inv_view[1]);
    ImGui::Text("eye      %.3f %.3f %.3f", eye.x, eye.y, eye.z);
    ImGui::Text("forward  %.3f %.3f %.3f", forward.x, forward.y, forward.z);
    ImGui::Text("up       %.3f %.3f %.3f", up.x, up.y, up.z);
    ImGui::Text("near %.4g  far %.4g  aspect %.4g  %s", c.clip.x, c.clip.y, c.clip.z, c.clip.w != 0 ? "ortho" : "perspective");
    matrix_rows("view", c.view);
    matrix_rows("proj", c.proj);
    matrix_rows("view_proj", c.view_proj);
    if (ImGui::TreeNode("frustum corners (world)")) {
        // ndc (x, y) = (+-1, +-1) at depth 0 (near) and 1 (far; none for an infinite far plane).
        for (float z : {0.0f, 1.0f}) {
            if (z == 1.0f && std::isinf(c.clip.y)) {
                ImGui::TextDisabled("far: at infinity");
                continue;
            }
            for (glm::vec2 xy : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
                glm::vec4 p = c.inv_view_proj * glm::vec4(xy, z, 1.0f);
                p /= p.w;
                ImGui::Text("%s %+.0f %+.0f  %8.3f %8.3f %8.3f", z == 0 ? "near" : "far ", xy.x, xy.y, p.x, p.y, p.z);
            }
        }
        ImGui::TreePop();
    }
    ImGui::TreePop();
}

} // namespace

void cameras_section(const exec::Executor& ex) {
    ImGui::Text("accum_frame %d", ex.accum_frame());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("frames since a param, the camera or the view size changed (progressive renders restart at 0)");
    const auto& cams = ex.graph().desc.cameras;
    if (cams.empty()) {
        ImGui::TextDisabled("no [cameras]");
        return;
    }
    if (!ex.camera_error().empty())
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s (showing the last valid values)", ex.camera_error().c_str());
    const auto& entries = ex.camera_entries();
    const auto& first = ex.cameras_first();
    if (first.size() != cams.size()) return;  // before the first frame
    static const char* kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    for (size_t i = 0; i < cams.size(); ++i) {
        const auto& c = cams[i];
        const exec::CameraBlock& e = entries[static_cast<size_t>(first[i])];
        if (!c.cube) {
            camera_entry(("cameras." + c.name).c_str(), e);
            continue;
        }
        if (!ImGui::TreeNode(("cameras." + c.name + "[6] (cube)").c_str())) continue;
        for (int f = 0; f < 6; ++f)
            camera_entry(("face " + std::to_string(f) + " " + kFaces[f]).c_str(), entries[static_cast<size_t>(first[i] + f)]);
        ImGui::TreePop();
    }
}

} // namespace pl::lab
