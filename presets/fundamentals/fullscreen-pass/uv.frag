#version 450
// The interpolated uv of the fullscreen triangle, stored as it arrives (rg of an rgba32f target)
// for the test that compares it with the pixel centres.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 uv_out;
void main() { uv_out = vec4(uv, 0.0, 1.0); }
