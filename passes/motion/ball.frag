#version 450
// The ball in constant colour (so the tests can count taps), its velocity in pixels per frame
// (xy) and its view depth (z).
#include "velocity.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec4 v_clip_now;
layout(location = 2) in vec4 v_clip_prev;
layout(location = 3) in float v_view_depth;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 velocity;
void main() {
    color = vec4(params.ball, 1.0);
    velocity = vec4(velocity_pixels(v_clip_now, v_clip_prev), v_view_depth, 1.0);
}
