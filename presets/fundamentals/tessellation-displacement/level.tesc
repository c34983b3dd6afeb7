#version 450
// Hull / tessellation control shader (000_c9f7e5de708ecbb3.txt L239-264: vertex shader ->
// hull shader -> tessellator -> domain shader): one invocation per output control point,
// passing the triangle's corners on, and the tessellation levels for the fixed-function
// tessellator. Uniform level L on all three edges and inside: with equal spacing an integer L
// splits each edge into L segments; the inside is filled with concentric rings (L - 2k
// segments per side of ring k), 1.5 L^2 triangles for even L, 1.5 L^2 - 0.5 for odd L (not
// the L^2 of a uniform subdivision: preset.toml and README).
layout(vertices = 3) out;
layout(location = 0) in vec3 v_pos[];
layout(location = 0) out vec3 c_pos[];
void main() {
    c_pos[gl_InvocationID] = v_pos[gl_InvocationID];
    if (gl_InvocationID == 0) {
        float L = params.level;
        gl_TessLevelOuter[0] = L;
        gl_TessLevelOuter[1] = L;
        gl_TessLevelOuter[2] = L;
        gl_TessLevelInner[0] = L;
    }
}
