#version 450
// The physically based model of 002_644d46bdce7e5305.txt L82-310 (after Karis, "Real Shading in
// Unreal Engine 4"):
//   f = diffuse / pi + D F V,        D: GGX (a = r^2),  F: Schlick,  V = G / (4 n.l n.v)
//   diffuse  = base (1 - metallic)                     (002 L275; L91: albedo, not "diffuse")
//   F0 = spec = mix(0.08 specular, base, metallic)     (002 L276; dielectrics ~4%, metals tinted)
// n.l and n.v are clamped to [1e-5, 1] as in 002. V is 002's Smith-GGX or Schlick-GGX
// (k = r^2/2); both contain the 1/(4 n.l n.v), so nothing divides by it here. The ambient is a
// uniform sky: diffuse gets it times base, specular times the Fresnel of n.v (a crude stand-in
// for the IBL of envmap/ibl-split-sum).
#include "common/brdf.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec2 v_material;
layout(location = 0) out vec4 hdr;

vec3 schlick(vec3 f0, float vh) { return f0 + (1.0 - f0) * pow(1.0 - vh, 5.0); }

void main() {
    float metallic = v_material.x, r = v_material.y;
    vec3 n = normalize(v_normal), l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    vec3 h = normalize(l + v);
    float nl = clamp(dot(n, l), 1e-5, 1.0), nv = clamp(dot(n, v), 1e-5, 1.0), nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);
    vec3 diffuse = params.base_color * (1.0 - metallic);
    vec3 f0 = mix(vec3(0.08 * params.specular), params.base_color, metallic);
    float V = params.visibility == VISIBILITY_SMITH_GGX ? v_smith_ggx(nv, nl, r) : v_schlick_ggx(nv, nl, r);
    vec3 spec = ndf_ggx(nh, r) * schlick(f0, vh) * V;
    vec3 direct = (diffuse / kPi + spec) * params.intensity * (dot(n, l) > 0.0 ? nl : 0.0);
    vec3 ambient = params.ambient * (diffuse + schlick(f0, nv));
    hdr = vec4(direct + ambient, 1.0);
}
