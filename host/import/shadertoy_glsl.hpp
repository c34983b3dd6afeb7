// The GLSL passlab generates around Shadertoy tabs: the shared uniform header and each pass's
// wrapper (channels, Common, the tab, a main() with Shadertoy's fragCoord).
#pragma once

#include "import/toy.hpp"

#include <array>
#include <string>

namespace pl::import {

// shadertoy.glsl: iResolution, iMouse, iDate, iFrameRate, iChannelTime, iSampleRate over the
// frame block and the `date` param (iTime, iTimeDelta, iFrame come from the host preamble).
std::string shadertoy_header();

// What a channel is to the wrapper: its GLSL sampler type and a comment.
struct ChannelDecl {
    std::string type = "sampler2D";  // sampler2D | samplerCube | sampler3D
    std::string comment;
};

// <tab>.frag: #includes shadertoy.glsl, declares iChannel0..3, #includes common.glsl (when
// there is one) and the tab's file, and calls mainImage (mainCubemap for Cube A).
std::string pass_wrapper(const Tab& tab, const std::array<ChannelDecl, 4>& channels, bool has_common);

// The sky a cube-map stand-in shows (a baked pass rendering the six faces).
std::string sky_cube_shader();
// The pass that draws frame.keys (the window's keyboard, exec/keyboard.hpp) into Shadertoy's
// 256x3 keyboard texture: row 0 held down, row 1 pressed this frame, row 2 toggled.
std::string keyboard_shader();

} // namespace pl::import
