#version 450
// Draws passes/aa/shapes.glsl: 3 vertices per triangle, kShapeTriangles triangles
// (vertex_count = 24). SCENE: 0 shapes, 1 edge, 2 full-view texture (an int expression, e.g.
// params.scene).
#include "aa/shapes.glsl"
layout(location = 0) flat out vec3 v_color;
layout(location = 1) out vec2 v_uv;
void main() {
    int t = gl_VertexIndex / 3, v = gl_VertexIndex % 3;
    vec2 uv = shape_vertex(SCENE, t, v);
    v_color = shape_color(SCENE, t);
    v_uv = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.5, 1.0);
}
