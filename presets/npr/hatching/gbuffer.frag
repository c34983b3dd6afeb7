#version 450
// The G-buffer for illustrations (000_c9f7e5de708ecbb3.txt L3229-3240): the normal (nx, ny, nz),
// the screen depth (sz, in the depth attachment) and the surface coordinates (ou, ov) "on the
// curved surface" that the strokes follow. (The slide labels nx "normal vector z": a typo for x.)
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 0) out vec4 normal;
layout(location = 1) out vec2 surface_uv;
void main() {
    normal = vec4(normalize(gl_FrontFacing ? v_normal : -v_normal), 1.0);
    surface_uv = v_uv;
}
