#version 450
// Background behind everything (it is at the far plane: fog covers it in every mode).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() { color = vec4(mix(vec3(0.75, 0.85, 1.0), vec3(0.3, 0.5, 0.85), 1.0 - uv.y), 1.0); }
