#version 450
// Constants only, each probed exactly.
layout(location = 0) out vec4 color;
void main() {
    color = vec4(0.5 * 0.25, 0.25, 0.0, 1.0);
}
