#version 450
// Per pixel (000 L2366-2381, 001_fe43b953f362fae7.txt L400-410): the interpolated normal is
// renormalised and the same Blinn-Phong evaluated for every fragment. Alpha marks coverage.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_color;
layout(location = 0) out vec4 color;
vec3 blinn_phong(vec3 n, vec3 p) {
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - p), h = normalize(l + v);
    float d = max(dot(n, l), 0.0);
    return vec3(0.6, 0.35, 0.25) * d + vec3(d > 0.0 ? pow(max(dot(n, h), 0.0), params.shininess) : 0.0);
}
void main() {
    vec3 n = normalize(v_normal);
    color = vec4(params.mode == MODE_PER_VERTEX ? v_color : blinn_phong(n, v_world), n.z);
}
