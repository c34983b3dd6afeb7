// The named cameras of a frame: [cameras] evaluated at the current params into the entries of
// the `cameras` block (one per camera, six per cube camera, in the order written), and the frame
// block of a pass rendered from one of them.
#pragma once

#include "exec/frame_block.hpp"
#include "graph/camera_values.hpp"

#include <vector>

namespace pl::exec {

// The block entry of a camera (face: 0..5 of a cube camera, else 0).
CameraBlock camera_block(const graph::CameraValues& v, int face);

// Every camera of the graph at `env`, in block order; the first entry of camera i is first[i].
struct CameraEntries {
    std::vector<CameraBlock> entries;
    std::vector<int> first;
};
Result<CameraEntries> eval_cameras(const std::vector<graph::CameraDesc>& cameras, const graph::SizeEnv& env);

// The camera part of a frame block (view .. camera_pos, aspect) from an entry; jitter is the
// view's alone, so a camera's frame has none.
void apply_camera(FrameBlock& fb, const CameraBlock& c, const glm::mat4& prev_view_proj);

// Whether the pass renders from a cube camera (mirror-image faces: the front face is flipped).
bool renders_cube_faces(const graph::GraphDesc& g, const graph::PassDesc& pd);

} // namespace pl::exec
