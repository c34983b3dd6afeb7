#version 450
// EXERCISE — image-based lighting with the split sum (002_644d46bdce7e5305.txt L419-541):
//   specular = prefiltered(R, lod) * (specColor * LUT.x + LUT.y)         (002 L328-336, L540)
//   diffuse  = base (1 - metallic) / pi * E(N)          (irradiance map, envmap/irradiance-env)
// TODO 4 is in exercise/prefilter.frag.
//     passlab run   envmap/ibl-split-sum --exercise presets/envmap/ibl-split-sum/exercise
//     passlab grade envmap/ibl-split-sum --exercise presets/envmap/ibl-split-sum/exercise
// The maps: `prefiltered`, a cube whose mip level k (0..5) was prefiltered for roughness k / 5;
// `lut`, the table of envmap/ibl-brdf-lut, x = roughness, y = n.v, (r, g) = (scale, bias) on
// F0; `irradiance`, E(N). kPi is in passes/common/brdf.glsl (included by brdf_lut.glsl).
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
    vec3 spec_color = mix(vec3(0.08 * params.specular), params.base_color, metallic);  // F0
    // TODO 1: the mip level to read for roughness r (002 L525-535: lod = remapped roughness *
    // maxMip). 002 leaves the remap open; this preset's prefilter made level k for roughness
    // k / kMaxLevel, so the remap must land each roughness on the level made for it.
    float lod = 0.0;
    // TODO 2: the split sum (002 L540): the table's (scale, bias) at (roughness, n.v), and the
    // prefiltered environment at R and lod times the BRDF's integral F0 * scale + bias.
    vec2 ab = vec2(1.0, 0.0);
    vec3 spec = vec3(0.0);
    // TODO 3: the diffuse part from the irradiance map looked up by the normal: the Lambert
    // reflectance of the non-metallic part (envmap/irradiance-env).
    vec3 diffuse = vec3(0.0);
    hdr = vec4(diffuse + spec, 1.0);
    ratio = spec.r / max(ab.x + ab.y, 1e-6);
}
