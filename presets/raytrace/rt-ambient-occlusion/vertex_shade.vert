#version 450
// Test-only: the mesh drawn with V traced at its vertices (trace_vertices; vertex i at texel
// (i % w, i / w)) and interpolated by the rasteriser, like a per-vertex AO bake (000 L4876:
// "n rays per vertex"). The view's shading gets V per pixel instead, traced at half resolution
// and upsampled: where both have converged they must agree.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out float v_id;
layout(location = 3) out float v_ao;
uniform sampler2D vertex_ao;

void main() {
    int w = textureSize(vertex_ao, 0).x;
    v_ao = texelFetch(vertex_ao, ivec2(gl_VertexIndex % w, gl_VertexIndex / w), 0).r;
    v_world = position;
    v_normal = normal;
    v_id = uv.x;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
