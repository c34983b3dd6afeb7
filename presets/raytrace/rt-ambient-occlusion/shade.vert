#version 450
// The fullscreen triangle of the shade pass (passlab's own: vertices (0,0), (2,0), (0,2) in uv),
// which also hands shade.frag the light direction: a constant of the frame, computed here for
// three vertices instead of for every pixel (issue #21; flat, so every pixel gets its bits).
#include "lighting.glsl"
layout(location = 0) out vec2 uv;
layout(location = 1) flat out vec3 v_light;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    v_light = rtao_light_direction();
}
