#version 450
// Vertex shader of the tessellated passes: positions pass through untouched (object space =
// world space here); the tessellation evaluation shader projects. SINGLE_PATCH: no mesh, one
// triangle patch from gl_VertexIndex (the counting pass).
#ifndef SINGLE_PATCH
layout(location = 0) in vec3 position;
#endif
layout(location = 0) out vec3 v_pos;
#ifdef SINGLE_PATCH
const vec3 kCorners[3] = vec3[](vec3(-0.8, 0.0, -0.6), vec3(0.8, 0.0, -0.6), vec3(0.0, 0.0, 0.8));
#endif
void main() {
#ifdef SINGLE_PATCH
    v_pos = kCorners[gl_VertexIndex];
#else
    v_pos = position;
#endif
    gl_Position = vec4(v_pos, 1.0);
}
