#version 450
// Debug pass: shows the fullscreen uv (red = u, green = v), so orientation is visible at a
// glance: black at the top-left, red at the top-right, green at the bottom-left.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main() { color = vec4(uv, 0.0, 1.0); }
