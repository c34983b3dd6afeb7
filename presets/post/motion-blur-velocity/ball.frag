#version 450
// The ball in constant colour (so the tests can count taps) and its velocity.
#include "velocity.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec4 v_clip_now;
layout(location = 2) in vec4 v_clip_prev;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 velocity;
void main() {
    color = vec4(params.ball, 1.0);
    velocity = vec4(velocity_pixels(v_clip_now, v_clip_prev), 0.0, 1.0);
}
