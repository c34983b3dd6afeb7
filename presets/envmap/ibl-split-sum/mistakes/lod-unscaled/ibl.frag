#version 450
// Image-based lighting with the split sum (002_644d46bdce7e5305.txt L419-541):
//   specular = prefiltered(R, lod = roughness * maxMip) * (specColor * LUT.x + LUT.y)
//   diffuse  = base (1 - metallic) / pi * E(N)          (irradiance map, envmap/irradiance-env)
// The roughness -> mip remap is "not perfect" in 002 and left open: ours is linear, level k
// prefiltered for roughness k / 5 (so roughness maps exactly onto the level it was made for).
#include "envmap/brdf_lut.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec2 v_material;  // metallic, roughness
layout(location = 0) out vec4 hdr;
layout(location = 1) out float ratio;
uniform samplerCube prefiltered;
uniform samplerCube irradiance;
uniform sampler2D lut;
const float kMaxLevel = 5.0;
void main() {
    float metallic = v_material.x, r = v_material.y;
    vec3 n = normalize(v_normal), v = normalize(frame.camera_pos.xyz - v_world);
    vec3 R = reflect(-v, n);
    float nv = clamp(dot(n, v), 1e-5, 1.0);
    vec3 spec_color = mix(vec3(0.08 * params.specular), params.base_color, metallic);
    vec2 ab = texture(lut, vec2(r, nv)).rg;
    vec3 spec = textureLod(prefiltered, R, r).rgb * (spec_color * ab.x + ab.y);
    vec3 diffuse = params.base_color * (1.0 - metallic) / kPi * texture(irradiance, n).rgb;
    hdr = vec4(diffuse + spec, 1.0);
    ratio = spec.r / max(ab.x + ab.y, 1e-6);
}
