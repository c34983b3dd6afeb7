#version 450
// One instance per sprite, 6 vertices (two triangles) each: the quad of
// 000_c9f7e5de708ecbb3.txt L3689-3731, turned to the viewer in the vertex shader.
#include "sprites.glsl"
layout(location = 0) out vec2 corner;
layout(location = 1) flat out int sprite;
void main() {
    corner = pl_quad_corner(gl_VertexIndex);
    sprite = gl_InstanceIndex;
    gl_Position = frame.view_proj * vec4(sprite_corner(gl_InstanceIndex, corner), 1.0);
}
