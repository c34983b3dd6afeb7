#version 450
// Fill: Lambert shading times a smooth pattern of the world position (so a comparison sees the
// position field, not only coverage). WIRE: the edges in dark grey over the fill.
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;
layout(location = 0) out vec4 color;
void main() {
#if WIRE
    color = vec4(0.08, 0.08, 0.1, 1.0);
#else
    vec3 n = normalize(v_normal);
    float l = 0.25 + 0.75 * max(dot(n, normalize(vec3(0.4, 0.8, 0.45))), 0.0);
    vec3 base = FLOOR != 0 ? vec3(0.75, 0.72, 0.62) * (0.85 + 0.15 * sin(3.0 * v_world.x) * sin(3.0 * v_world.z))
                           : vec3(0.85, 0.45, 0.3);
    color = vec4(base * l, 1.0);
#endif
}
