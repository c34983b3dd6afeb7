// The per-frame uniform block every shader sees as `frame`, defined once here for both sides:
// the C++ struct (std140) and the GLSL text generated from kFrameBlockGlsl; static_asserts keep
// them from drifting apart. Likewise the per-camera struct of the `cameras` block.
#pragma once

#include "graph/desc.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>

namespace pl::exec {

struct FrameBlock {
    glm::mat4 view;            // world -> view
    glm::mat4 proj;            // view -> clip (Vulkan, y flipped, depth 0..1), jitter applied
    glm::mat4 view_proj;
    glm::mat4 inv_view;
    glm::mat4 inv_proj;
    glm::mat4 inv_view_proj;
    glm::mat4 prev_view_proj;  // last frame's view_proj (motion vectors, TAA reprojection)
    glm::vec4 camera_pos;      // xyz world position, w = 1
    glm::vec4 resolution;      // w, h, 1/w, 1/h of the view (a pass with `camera`: its render area)
    glm::vec4 mouse;           // Shadertoy iMouse: xy current (pixels) while down, zw click position
    glm::vec4 jitter;          // xy this frame's sub-pixel jitter in pixels, zw last frame's
    float time;                // seconds
    float delta;               // seconds since last frame (the fixed step when headless)
    int32_t index;             // frame number, 0 for the first frame
    float aspect;              // the projection's width / height (the view's, or the pass camera's)
    int32_t accum_frame;       // frames since the camera, view size or a param last changed (0 = changed)
    int32_t pad_[3];
    glm::vec4 target;          // w, h, 1/w, 1/h of the pass's render area (compute: the view)
    glm::uvec4 keys[6];        // keyboard bits, exec/keyboard.hpp: row r key k = bit k%32 of word r*8 + k/32
};

static_assert(offsetof(FrameBlock, camera_pos) == 448);
static_assert(offsetof(FrameBlock, resolution) == 464);
static_assert(offsetof(FrameBlock, mouse) == 480);
static_assert(offsetof(FrameBlock, jitter) == 496);
static_assert(offsetof(FrameBlock, time) == 512);
static_assert(offsetof(FrameBlock, index) == 520);
static_assert(offsetof(FrameBlock, accum_frame) == 528);
static_assert(offsetof(FrameBlock, target) == 544);
static_assert(offsetof(FrameBlock, keys) == 560);
static_assert(sizeof(FrameBlock) == 656);

// The blocks carry explicit bindings (frame 0, params 1 in set 0) only so that user resources
// auto-mapped around them never collide; the host binds them by block name like everything else.

// Mirrors FrameBlock member for member; std140 gives the offsets asserted above.
inline constexpr const char* kFrameBlockGlsl = R"(layout(set = 0, binding = 0, std140) uniform PasslabFrame {
    mat4 view;
    mat4 proj;
    mat4 view_proj;
    mat4 inv_view;
    mat4 inv_proj;
    mat4 inv_view_proj;
    mat4 prev_view_proj;
    vec4 camera_pos;
    vec4 resolution;
    vec4 mouse;
    vec4 jitter;
    float time;
    float delta;
    int index;
    float aspect;
    int accum_frame;
    vec4 target;
    uvec4 keys[6];
} frame;
)";

// One named camera (or cube face) as shaders see it in the `cameras` block: `cameras.sun`,
// `cameras.probe[face]` (exec/preamble.cpp generates the block from [cameras]).
struct CameraBlock {
    glm::mat4 view;           // world -> camera
    glm::mat4 proj;           // camera -> clip (Vulkan, depth 0..1; far = inf: infinite)
    glm::mat4 view_proj;
    glm::mat4 inv_view;
    glm::mat4 inv_proj;
    glm::mat4 inv_view_proj;
    glm::vec4 position;       // xyz eye, w = 1
    glm::vec4 clip;           // near, far (may be +inf), aspect, 1 for ortho else 0
};
static_assert(offsetof(CameraBlock, position) == 384);
static_assert(sizeof(CameraBlock) == 416);  // std140: array stride of PasslabCamera
static_assert(graph::kMaxCameraEntries * sizeof(CameraBlock) <= 16384, "cameras must fit the minimum maxUniformBufferRange");

inline constexpr const char* kCameraStructGlsl = R"(struct PasslabCamera {
    mat4 view;
    mat4 proj;
    mat4 view_proj;
    mat4 inv_view;
    mat4 inv_proj;
    mat4 inv_view_proj;
    vec4 position;
    vec4 clip;
};
)";
// The block's binding: after frame (0) and params (1), for the same reason as theirs.
inline constexpr int kCamerasBinding = 2;

// Push constants: which iteration of a repeated pass is running.
struct PushBlock {
    int32_t iteration;  // 0 .. count-1
    int32_t count;      // the pass's repeat count
    int32_t layer;      // layer/face being rendered (== iteration for layer = "iteration")
    int32_t group_iteration;  // the [[group]]'s iteration (0 outside a group)
};
static_assert(sizeof(PushBlock) == 16);

inline constexpr const char* kPushBlockGlsl = R"(layout(push_constant) uniform PasslabPush {
    int iteration;
    int count;
    int layer;
    int group_iteration;
} pl_push;
#define pl_iteration pl_push.iteration
#define pl_iteration_count pl_push.count
#define pl_layer pl_push.layer
#define pl_group_iteration pl_push.group_iteration
)";

} // namespace pl::exec
