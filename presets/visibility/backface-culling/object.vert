#version 450
// A 4 x 3 grid of tori, each turned differently (closed meshes: every back face is hidden by a
// front face of the same object, so culling them changes no pixel, 000_c9f7e5de708ecbb3.txt
// L6110-6125).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) flat out uint v_instance;
mat3 rot(vec3 a) {
    vec3 c = cos(a), s = sin(a);
    mat3 x = mat3(1, 0, 0, 0, c.x, s.x, 0, -s.x, c.x);
    mat3 y = mat3(c.y, 0, -s.y, 0, 1, 0, s.y, 0, c.y);
    mat3 z = mat3(c.z, s.z, 0, -s.z, c.z, 0, 0, 0, 1);
    return z * y * x;
}
void main() {
    int i = gl_InstanceIndex;
    vec3 centre = vec3(float(i % 4) * 1.9 - 2.85, float(i / 4) * 1.7 - 1.7, 0.0);
    mat3 r = rot(vec3(0.7, 1.3, 0.4) * float(i + 1));
    v_normal = r * normal;
    v_instance = uint(i);
    gl_Position = frame.view_proj * vec4(centre + r * position, 1.0);
}
