#version 450
// The surface attributes of the Cornell box into three targets. From the view (G-buffer):
//   0 = albedo, 1 = world normal, 2 = world position (w = 1 on geometry, 0 = background).
// From the light with RSM_FLUX (the reflective shadow map, 000_c9f7e5de708ecbb3.txt L5332-5359:
// "store additional information on received light"), target 0 is instead the texel's reflected
// flux and target 2's w its surface area (for the near-field clamp of the gather):
//   Phi_p = rho * I(w_p) * dOmega_p,   dOmega_p = texel area on the unit image plane * cos^3(axis),
// the spot's intensity times the solid angle the texel subtends (the surface's cosine and the
// 1/d^2 of the irradiance cancel against the texel's footprint area dOmega d^2 / cos).
#include "gi/cornell.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec3 v_albedo;
layout(location = 0) out vec4 o_attr;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_position;
void main() {
    vec3 n = normalize(v_normal);
#ifdef RSM_FLUX
    vec3 d = v_world - CORNELL_LIGHT_POS;
    float dist = length(d);
    vec3 w = d / dist;
    vec3 lv = (cameras.light.view * vec4(v_world, 1.0)).xyz;  // light view space, looks along -z
    float cos_axis = -lv.z / length(lv);
    float side = 2.0 / abs(cameras.light.proj[1][1]) / frame.target.y;  // texel side at distance 1
    float d_omega = side * side * cos_axis * cos_axis * cos_axis;
    float cos_in = max(dot(n, -w), 0.0);
    vec3 flux = cos_in > 0.0 ? v_albedo * cornell_light_intensity(w) * d_omega * params.flux_scale : vec3(0.0);
    float area = d_omega * dist * dist / max(cos_in, 0.05);
    o_attr = vec4(flux, 1.0);
    o_position = vec4(v_world, area);
#else
    o_attr = vec4(v_albedo, 1.0);
    o_position = vec4(v_world, 1.0);
#endif
    o_normal = vec4(n, 0.0);
}
