#version 450
// Pass 1: plain two-tone shading of the surface.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 color;
const vec3 kLight = vec3(0.45, 0.8, 0.4);
void main() {
    vec3 n = normalize(gl_FrontFacing ? v_normal : -v_normal);
    float lit = dot(n, normalize(kLight)) > 0.2 ? 1.0 : 0.72;
    color = vec4(params.base * lit, 1.0);
}
