#version 450
// The object in world space: the mesh scaled by STRETCH (x, y, z) and moved by OFFSET. Its
// normals go through the inverse transpose of that scale (1 / STRETCH) — a non-uniform scale
// would otherwise tilt them — and are left unnormalised here; the users normalise.
// VISIBLE (an expression) hides the mesh (every vertex outside the clip volume) when false.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
#ifndef OFFSET
#define OFFSET vec3(0.0)
#endif
#ifndef STRETCH
#define STRETCH vec3(1.0)
#endif
void main() {
    v_world = position * STRETCH + OFFSET;
    v_normal = normal / STRETCH;  // inverse transpose of diag(STRETCH)
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
#ifdef VISIBLE
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
#endif
}
