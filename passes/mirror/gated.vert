#version 450
// The host's fullscreen triangle (uv (0,0) = top-left), skipped entirely when VISIBLE (an
// expression) is false: check-only passes then cost nothing instead of a discard per pixel.
layout(location = 0) out vec2 uv;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    gl_Position = (VISIBLE) ? vec4(p * 2.0 - 1.0, 0.0, 1.0) : vec4(0.0, 0.0, -2.0, 1.0);
}
