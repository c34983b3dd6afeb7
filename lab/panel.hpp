// The live lab's panel, drawn with Dear ImGui every frame: params (widgets generated from
// [params]), time controls, the pass list with GPU times and a frame-time graph, the image
// viewer's controls, the reload-error overlay and the keyboard help. It edits a LabState and
// the executor's param values; run.cpp acts on the requests it leaves there.
#pragma once

#include "exec/executor.hpp"
#include "image_stats.hpp"
#include "viewer.hpp"

#include <array>
#include <deque>
#include <map>
#include <optional>
#include <string>

namespace pl::lab {

// The panel is docked left of the view, this wide in screen units at content scale 1: the window
// grows by it (the view keeps its size), so the panel never covers the picture.
constexpr float kPanelWidth = 360.0f;

struct LabState {
    // Frame clock.
    bool paused = false;
    bool step = false;       // advance one 1/60 s step while paused (consumed by run.cpp)
    double time = 0.0;
    float speed = 1.0f;
    // Panels.
    bool show_ui = true, show_help = false, show_viewer = false;
    int dock_px = 0;  // the docked panel's width in framebuffer pixels (0 while hidden): the view starts there
    std::deque<float> frame_ms;  // CPU time per frame, newest last
    std::optional<Error> error;  // the last failed reload; cleared by a good one
    // Image viewer.
    std::string viewer_image;
    int viewer_mip = 0, viewer_layer = 0;
    ViewerMapping viewer_mapping;
    ViewerView viewer_view;          // zoom and pan (wheel and drag over the view while it shows)
    bool viewer_auto_exposure = false;  // exposure from the image's 99th percentile, every frame
    image::Image viewer_pixels;  // the last readback, for texel values under the cursor
    ImageStats viewer_stats;     // of viewer_pixels, for the channel shown
    // Param values set in the panel, re-applied after every reload so edits to a shader never
    // reset what the user dialled in.
    std::map<std::string, std::array<double, 4>> touched;
    // Requests for run.cpp.
    bool save_sidecar = false, screenshot = false, reset_camera = false, reset_params = false;
    std::string copy_line;  // "--set ..." text put on the clipboard
    std::string status;     // one-line feedback ("saved to ...")
};

// `viewer` may be null (no texture yet). `preset` is the preset folder (absolute) that the
// copy-as-command line renders.
void draw_panel(LabState& s, exec::Executor& ex, const ViewerTexture* viewer, const std::string& preset);

// The named cameras' values and frustums, and frame.accum_frame (panel_cameras.cpp).
void cameras_section(const exec::Executor& ex);

// The `--set` arguments reproducing the current values of the touched params.
std::vector<std::string> set_arguments(const exec::Executor& ex, const LabState& s);

} // namespace pl::lab
