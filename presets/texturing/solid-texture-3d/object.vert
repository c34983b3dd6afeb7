#version 450
// The mesh moved to params.object_offset (a translation: the model matrix of a moving object).
// v_object is the mesh's own, object-space position, what the solid texture is evaluated at
// (000_c9f7e5de708ecbb3.txt L1721-1725: "directly map object space T(x, y, z)"); v_world is
// where the point is drawn. With the default offset 0 the two are equal. VISIBLE (an
// expression) hides the mesh.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_object;
void main() {
    v_object = position;
    v_world = position + params.object_offset;
    v_normal = normal;                     // a translation leaves normals alone
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
