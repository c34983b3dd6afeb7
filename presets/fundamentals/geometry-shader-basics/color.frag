#version 450
// The geometry shader's colour, and 1 per fragment into the additive coverage target.
layout(location = 0) in vec3 g_color;
layout(location = 0) out vec4 color;
layout(location = 1) out float coverage;
void main() {
    color = vec4(g_color, 1.0);
    coverage = 1.0;
}
