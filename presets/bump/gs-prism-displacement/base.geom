#version 450
// Pass-through for the reference (undisplaced) mesh: two base passes share it, one per
// tessellation of the torus (preset.toml), and only the one that mesh_detail selects emits its
// triangles, so `base` always shows the mesh the prisms were built on.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec2 v_uv[];
layout(location = 2) in vec3 v_t[];
layout(location = 3) in vec3 v_b[];
layout(location = 4) in vec3 v_n[];
layout(location = 0) out vec3 g_world;
layout(location = 1) out vec2 g_uv;
layout(location = 2) out vec3 g_t;
layout(location = 3) out vec3 g_b;
layout(location = 4) out vec3 g_n;
void main() {
    if (params.mesh_detail != PRISM_MESH) return;
    for (int i = 0; i < 3; ++i) {
        g_world = v_world[i], g_uv = v_uv[i], g_t = v_t[i], g_b = v_b[i], g_n = v_n[i];
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
