#version 450
// Flat colour per object plus a fixed directional light; the wall is grey.
#include "visibility/scene.glsl"
layout(location = 0) in vec3 normal;
layout(location = 1) flat in int object;
layout(location = 0) out vec4 color;
void main() {
    vec3 base = object < 0 ? vec3(0.55) : pl_vis_color(object);
    float l = 0.35 + 0.65 * max(dot(normalize(normal), normalize(vec3(0.4, 0.8, 0.5))), 0.0);
    color = vec4(base * l, 1.0);
}
