#version 450
// The PBR presets' 2 x 5 sphere grid (10 instances): row 0 dielectric, row 1 metal; roughness
// 0.1, 0.3, 0.5, 0.75, 1 left to right. ALL_METAL (an expression) makes every sphere metallic.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec2 v_material;  // metallic, roughness
const float kRoughness[5] = float[](0.1, 0.3, 0.5, 0.75, 1.0);
#ifndef ALL_METAL
#define ALL_METAL false
#endif
// SINGLE_MATERIAL (an optional vec2 expression: metallic, roughness): when its x is >= 0, every
// instance is one sphere at the origin with that material, for closed-form test cases (the
// centre pixel then has n = v on the camera's axis).
#ifndef SINGLE_MATERIAL
#define SINGLE_MATERIAL vec2(-1.0)
#endif
void main() {
    int col = gl_InstanceIndex % 5, row = gl_InstanceIndex / 5;
    vec3 p = position + vec3((float(col) - 2.0) * 1.15, row == 0 ? 0.6 : -0.6, 0.0);
    v_material = vec2((ALL_METAL) ? 1.0 : float(row), kRoughness[col]);
    vec2 single = SINGLE_MATERIAL;
    if (single.x >= 0.0) p = position, v_material = single;
    v_world = p;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
