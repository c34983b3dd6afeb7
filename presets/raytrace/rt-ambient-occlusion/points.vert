#version 450
// Test-only: every vertex of the mesh as one texel (vertex i -> texel (i % w, i / w)) of a
// "G-buffer of vertices", so the same ray-tracing pass that shades the view computes V at the
// mesh's vertices, where precomputed-ao's definition can be evaluated too.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;  // uv.x = patch id
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out float v_id;

void main() {
    vec2 size = frame.target.xy;
    vec2 texel = vec2(gl_VertexIndex % int(size.x), gl_VertexIndex / int(size.x)) + 0.5;
    v_world = position;
    v_normal = normal;
    v_id = uv.x;
    gl_Position = vec4(texel / size * 2.0 - 1.0, 0.0, 1.0);
    gl_PointSize = 1.0;
}
