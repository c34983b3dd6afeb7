#version 450
// EXERCISE — adding the bloom back (000_c9f7e5de708ecbb3.txt L3092, "add filtered image to
// original image"; 002_644d46bdce7e5305.txt L714). `bloom` is the blurred bright image at
// quarter resolution (the sampler upsamples it bilinearly), `hdr` the scene's HDR radiance.
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
layout(location = 1) out vec4 added;
uniform sampler2D hdr;
uniform sampler2D bloom;
void main() {
    vec3 add = params.strength * texture(bloom, uv).rgb;
    if (params.split && uv.x < 0.5) add = vec3(0.0);
    vec3 base = texture(hdr, uv).rgb;

    // TODO 3: c, the light that reaches this pixel: the scene's radiance plus the bloom's light
    // (L3092). Then `result`: c exposed by params.exposure and tone mapped with tonemap_hejl
    // (passes/post/tonemap.glsl), whose output is already display-encoded (002 L618). Bloom is
    // light: in which space do two lights add?
    vec3 c = base;
    result = vec4(vec3(0.0), 1.0);

    if (params.split && abs(uv.x - 0.5) < 0.0015) result = vec4(1.0, 0.8, 0.2, 1.0);
    added = vec4(c - base, 1.0);  // what the composite really added (bloom-only-adds)
}
