// The text every user shader gets after its #version (frame block, params block, cameras block,
// push constants, Shadertoy aliases) and the host's own fullscreen vertex stage.
#pragma once

#include "graph/desc.hpp"

#include <string>

namespace pl::exec {

std::string preamble_source(const std::vector<graph::ParamDesc>& params, const std::vector<graph::CameraDesc>& cameras = {});
// The `cameras` block: one PasslabCamera member per camera of [cameras] (an array of 6 for a
// cube camera, in face order), in the order written; empty without cameras.
std::string cameras_glsl(const std::vector<graph::CameraDesc>& cameras);

// Fullscreen triangle; outputs `uv` at location 0 with (0,0) at the top-left texel of the
// target, matching how images are stored and sampled (not Shadertoy's bottom-left).
std::string fullscreen_vertex_source();

} // namespace pl::exec
