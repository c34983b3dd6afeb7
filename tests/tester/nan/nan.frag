#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    float zero = uv.x * 0.0;  // not a constant, so the compiler cannot fold it
    color = vec4(zero / zero, 0.0, 0.0, 1.0);
}
