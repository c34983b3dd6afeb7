#version 450
// Draws passes/aa/shapes.glsl: 3 vertices per triangle, kShapeTriangles triangles
// (vertex_count = 24). SCENE: 0 shapes, 1 edge, 2 full-view texture (an int expression, e.g.
// params.scene). Optional: SQUARE_OFFSET (vec2 expression, uv) moves the square, and
// JITTER_PX (vec2 expression, pixels) shifts everything by a sub-pixel jitter.
#include "aa/shapes.glsl"
#include "aa/taa_jitter.glsl"
layout(location = 0) flat out vec3 v_color;
layout(location = 1) out vec2 v_uv;
layout(location = 2) flat out int v_triangle;
#ifndef SQUARE_OFFSET
#define SQUARE_OFFSET vec2(0.0)
#endif
void main() {
    int t = gl_VertexIndex / 3, v = gl_VertexIndex % 3;
    vec2 uv = shape_vertex(SCENE, t, v) + shape_offset(SCENE, t, SQUARE_OFFSET);
    v_triangle = t;
    v_color = shape_color(SCENE, t);
    v_uv = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.5, 1.0);
#ifdef JITTER_PX
    gl_Position.xy += (JITTER_PX) * 2.0 * frame.resolution.zw;  // pixels -> NDC
#endif
}
