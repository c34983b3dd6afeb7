#version 450
// Keeps the result of two frames ago (tests): this pass copies last frame's result into an
// image with its own history, whose previous contents are then the result of frame n - 2.
layout(location = 0) out vec4 result_old;
uniform sampler2D result_prev;
void main() { result_old = texelFetch(result_prev, ivec2(gl_FragCoord.xy), 0); }
