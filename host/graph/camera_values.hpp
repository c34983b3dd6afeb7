// A named camera's values at one moment: its expressions evaluated over the view and the current
// params, and every range checked (fov in (0, 180), 0 < near < far, far = inf only for
// perspective and cube cameras, aspect and ortho_height > 0, eye != target). Used at build time
// (errors at the offending value) and by the executor every frame (params may have moved).
#pragma once

#include "graph/desc.hpp"
#include "graph/sizeexpr.hpp"

#include <array>

namespace pl::graph {

struct CameraValues {
    std::array<double, 3> eye{0, 0, 0}, target{0, 0, -1}, up{0, 1, 0};
    double fov = 45.0;  // vertical, degrees (cube: 90)
    double near = 0.05, far = 100.0;
    double aspect = 1.0;  // width / height (cube: 1)
    double ortho_height = 2.0;
    bool ortho = false, cube = false;
};

Result<CameraValues> eval_camera(const CameraDesc& c, const SizeEnv& env);

// The graph's params (and the view) as an expression environment: scalars for size expressions,
// every component for float expressions.
SizeEnv make_env(const GraphDesc& g, std::array<int, 2> view);

} // namespace pl::graph
