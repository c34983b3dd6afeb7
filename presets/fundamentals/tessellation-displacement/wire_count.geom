#version 450
// After the tessellator: every generated triangle passes here once. It gets barycentric
// corner colours for the wireframe overlay and, with COUNT, adds 1 to the counter `tris`
// (docs/catalogue.md says L^2 triangles for level L; the tessellator makes 1.5 L^2 for even L,
// 1.5 L^2 - 0.5 for odd: preset.toml, README).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 e_world[];
layout(location = 1) in vec3 e_normal[];
layout(location = 0) out vec3 g_world;
layout(location = 1) out vec3 g_normal;
layout(location = 2) out vec3 g_bary;
#ifdef COUNT
layout(std430) buffer tris { uint emitted; };
#endif
void main() {
#ifdef COUNT
    atomicAdd(emitted, 1u);
#endif
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        g_world = e_world[i];
        g_normal = e_normal[i];
        g_bary = vec3(i == 0, i == 1, i == 2);
        EmitVertex();
    }
    EndPrimitive();
}
