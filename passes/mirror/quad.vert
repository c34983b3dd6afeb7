#version 450
// A horizontal square |x|, |z| <= HALF at height Y (two counter-clockwise triangles seen from
// above, vertex_count = 6): the mirror (HALF = kMirrorHalf, Y = 0) or its frame.
//   VIEW_PROJ  the camera (default the view's); VISIBLE an expression as in scene.vert
#include "mirror/mirror.glsl"
#include "mirror/scene.glsl"
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
#ifndef VIEW_PROJ
#define VIEW_PROJ frame.view_proj
#endif
#ifndef VISIBLE
#define VISIBLE true
#endif
const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(-1, 1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(1, -1));
void main() {
    vec2 c = kCorners[gl_VertexIndex] * (HALF);
    v_world = vec3(c.x, Y, c.y);
    v_normal = kMirrorNormal;
    gl_Position = (VIEW_PROJ) * vec4(v_world, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
