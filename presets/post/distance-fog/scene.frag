#version 450
// c_s: simple Lambert on the ground and pillars; the test wall is unlit (its colour exactly).
layout(location = 0) in vec3 v_normal;
layout(location = 1) flat in int v_instance;
layout(location = 0) out vec4 color;
const vec3 kLight = vec3(0.4, 0.8, 0.45);
void main() {
#if KIND == 2
    color = vec4(params.wall_color, 1.0);
#else
    vec3 base = KIND == 0 ? vec3(0.35, 0.45, 0.25) : vec3(0.8, 0.55 + 0.05 * float(v_instance % 3), 0.4);
    float lit = 0.25 + 0.75 * max(dot(normalize(v_normal), normalize(kLight)), 0.0);
    color = vec4(base * lit, 1.0);
#endif
}
