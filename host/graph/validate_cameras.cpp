// [cameras] and the passes and tests that name them: every camera evaluates with valid values at
// the view (and at each test's params and overrides), every `camera = "NAME"` exists.
#include "graph/camera_values.hpp"
#include "graph/validate_parts.hpp"

namespace pl::graph {

namespace {

std::vector<std::string> camera_names(const GraphDesc& g) {
    std::vector<std::string> names;
    for (const auto& c : g.cameras) names.push_back(c.name);
    return names;
}

} // namespace

Status validate_cameras(const GraphDesc& g, const SizeEnv& env, const TestDesc* test) {
    for (const auto& c : g.cameras) {
        const CameraDesc* used = &c;
        if (test)
            if (auto it = test->cameras.find(c.name); it != test->cameras.end()) used = &it->second;
        if (auto v = eval_camera(*used, env); !v) {
            Error e = v.error();
            if (test) e.notes.push_back("in test '" + test->name + "'");
            return e;
        }
    }
    if (test) return ok_status();
    for (const auto& p : g.passes) {
        if (p.camera.empty() || g.find_camera(p.camera)) continue;
        Error e = ref_error("camera", p.camera, p.keys.at("camera", p.loc), p.name, camera_names(g), "cameras");
        if (g.cameras.empty()) e.hint = "declare it in [cameras], e.g. sun = { ortho = true, eye = [5, 10, 5], target = [0, 0, 0] }";
        return e;
    }
    return ok_status();
}

} // namespace pl::graph
