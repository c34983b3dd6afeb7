#version 450
// Per vertex (Gouraud, 000_c9f7e5de708ecbb3.txt L2366-2381): Blinn-Phong evaluated here and the
// colour interpolated. Per pixel: only the normal and position are passed on.
#include "common/brdf.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_color;
vec3 blinn_phong(vec3 n, vec3 p) {
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - p), h = normalize(l + v);
    float d = max(dot(n, l), 0.0);
    return vec3(0.6, 0.35, 0.25) * d + vec3(d > 0.0 ? pow(max(dot(n, h), 0.0), params.shininess) : 0.0);
}
void main() {
    v_world = position;
    v_normal = normal;
    v_color = blinn_phong(normalize(normal), position);
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
