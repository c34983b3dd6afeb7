#version 450
// World-space corners and normals for subdivide.geom, which projects after subdividing; with
// PROJECT the plain pipeline instead (the unsubdivided reference of the planar test).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    v_world = position + OFFSET;
    v_normal = normal;
#ifdef PROJECT
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
#else
    gl_Position = vec4(v_world, 1.0);
#endif
}
