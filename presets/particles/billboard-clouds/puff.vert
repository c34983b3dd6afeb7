#version 450
// One instance per puff, 6 vertices: the screen-aligned quad of passes/particles/billboard.glsl
// (000_c9f7e5de708ecbb3.txt L3708-3729: the model-view rotation removed, the scale kept), so
// each quad lies in a plane parallel to the image plane and its disc projects to a circle.
#include "clouds.glsl"
layout(location = 0) out vec2 corner;
void main() {
    corner = pl_quad_corner(gl_VertexIndex);
    int i = gl_InstanceIndex;
    gl_Position = frame.view_proj * vec4(pl_billboard_screen(puff_centre(i), corner, puff_size(i), frame.inv_view), 1.0);
}
