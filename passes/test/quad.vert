#version 450
// Test helper: draws axis-aligned quads given in NDC (Vulkan: y = -1 is the top row), six
// vertices per quad, one quad per instance or per group of six vertices. The quad rectangle,
// depth and colour come from the QUADS define: an array of vec4 rect (x0, y0, x1, y1), and
// DEPTHS / COLORS arrays of the same length.
layout(location = 0) flat out vec4 v_color;

const vec4 kRects[] = QUADS;
const float kDepths[] = DEPTHS;
const vec4 kColors[] = COLORS;

void main() {
    int q = gl_VertexIndex / 6 + gl_InstanceIndex;
    const ivec2 corner[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
    ivec2 c = corner[gl_VertexIndex % 6];
    vec4 r = kRects[q];
    gl_Position = vec4(c.x == 0 ? r.x : r.z, c.y == 0 ? r.y : r.w, kDepths[q], 1.0);
    v_color = kColors[q];
}
