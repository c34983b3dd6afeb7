#version 450
// Shading weighed by the baked visibility (000_c9f7e5de708ecbb3.txt L4867-4869):
//   I = (1 - AO) (k_a I_a + k_d I_d max(n . l, 0)),   1 - AO = V_AO (000 L4864)
// as printed, the direct term is darkened too (apply = all); apply = ambient darkens only the
// ambient term, which is what the occlusion actually measures (004 L690: constant light from
// every direction).
#include "ao/scene.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_atlas;
layout(location = 3) flat in int v_id;
layout(location = 0) out vec4 hdr;
uniform sampler2D ao_map;

vec3 albedo_of(int id) {
    if (id == 0) return vec3(0.75, 0.73, 0.7);
    if (id == 1) return vec3(0.85, 0.35, 0.25);
    if (id == 2) return vec3(0.3, 0.55, 0.85);
    if (id <= 8) return vec3(0.8, 0.75, 0.45);
    return vec3(0.6, 0.8, 0.6);
}

void main() {
    vec3 n = normalize(v_normal);
    // The bowl's inside and outside coincide: keep the side facing the eye (and cull the back of
    // every closed patch the same way).
    if (dot(n, frame.camera_pos.xyz - v_world) < 0.0) discard;
    vec4 baked = texture(ao_map, v_atlas);
    float v_ao = baked.r;
    vec3 l = normalize(vec3(cos(radians(params.light_elevation)) * cos(radians(params.light_azimuth)),
                            sin(radians(params.light_elevation)),
                            cos(radians(params.light_elevation)) * sin(radians(params.light_azimuth))));
    vec3 kd = albedo_of(v_id), ka = kd;
    // I_a: constant (as printed), or a sky-to-ground gradient looked up along the normal or
    // along the baked bent normal (000 L4865-4866: "used for advanced lighting instead of the
    // surface normal": light arrives from where the surface is open).
    vec3 lookup = params.sky_lookup == SKY_LOOKUP_BENT ? normalize(baked.gba) : n;
    vec3 i_a = params.sky_lookup == SKY_LOOKUP_OFF ? vec3(1.0) : mix(vec3(0.35, 0.3, 0.25), vec3(1.1, 1.15, 1.25), 0.5 + 0.5 * lookup.y);
    vec3 ambient = params.ambient * ka * i_a, direct = params.direct * kd * max(dot(n, l), 0.0);
    vec3 c;
    if (params.show == SHOW_AO) c = vec3(v_ao);
    else if (params.show == SHOW_BENT) c = 0.5 + 0.5 * normalize(baked.gba);
    else if (params.show == SHOW_NO_AO) c = ambient + direct;
    else c = params.apply == APPLY_ALL ? v_ao * (ambient + direct) : v_ao * ambient + direct;
    hdr = vec4(c, 1.0);
}
