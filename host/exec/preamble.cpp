#include "exec/preamble.hpp"

#include "exec/frame_block.hpp"
#include "exec/params.hpp"
#include "scene/scene_gpu.hpp"

namespace pl::exec {

std::string cameras_glsl(const std::vector<graph::CameraDesc>& cameras) {
    if (cameras.empty()) return {};  // no block at all: graphs without cameras compile as before
    std::string s = kCameraStructGlsl;
    s += "layout(set = 0, binding = " + std::to_string(kCamerasBinding) + ", std140) uniform PasslabCameras {\n";
    for (const auto& c : cameras) s += "    PasslabCamera " + c.name + (c.cube ? "[6]" : "") + ";\n";
    s += "} cameras;\n";
    return s;
}

std::string preamble_source(const std::vector<graph::ParamDesc>& params, const std::vector<graph::CameraDesc>& cameras) {
    std::string s;
    s += "#define PASSLAB 1\n";
    s += kFrameBlockGlsl;
    s += params_glsl(params);
    s += cameras_glsl(cameras);
    s += kPushBlockGlsl;
    // Structs of the host-built scene buffers (types only: no shader pays for them unless it
    // includes raytrace/bvh.glsl, which declares the buffer).
    s += scene::gpu::scene_glsl();
    // Shadertoy names, so snippets from there run unchanged (fragCoord is top-left based here).
    s += "#define iTime frame.time\n"
         "#define iTimeDelta frame.delta\n"
         "#define iFrame frame.index\n"
         "#define iResolution vec3(frame.resolution.xy, 1.0)\n"
         "#define iMouse frame.mouse\n";
    return s;
}

std::string fullscreen_vertex_source() {
    return R"(#version 450
layout(location = 0) out vec2 uv;
void main() {
    // One triangle covering the screen: vertices (0,0), (2,0), (0,2) in uv space.
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
}

} // namespace pl::exec
