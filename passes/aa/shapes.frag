#version 450
#include "aa/shapes.glsl"
layout(location = 0) flat in vec3 v_color;
layout(location = 1) in vec2 v_uv;
layout(location = 0) out vec4 color;
void main() { color = vec4(SCENE == 2 ? shape_texture(v_uv) : v_color, 1.0); }
