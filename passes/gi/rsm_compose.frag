#version 450
#extension GL_EXT_control_flow_attributes : require
// The picture of the GI presets that gather at low resolution (reflective-shadow-maps,
// instant-radiosity): direct light (shadow-mapped spot) plus the gathered indirect light,
//   L = L0 + rho/pi * E,   E = gi_irradiance (the preset's gather.glsl),
// E interpolated from the 1/RSM_DIV-resolution gather (gi/rsm_lowres.comp) with bilinear weights
// kept only for low-res samples on the same surface (normals within ~25 degrees, within 4 cm of
// this pixel's tangent plane), else from such samples in the 4x4 texels around; where none
// qualifies (silhouettes, small faces) the pixel gathers itself, as the RSM paper does (the gather by a macro-free call: each preset's gather.glsl
// defines gi_irradiance). Targets: `radiance` (linear, direct + indirect), `indirect`
// (linear, the indirect term alone), `ldr` (exposure, sRGB on store).
#include "gather.glsl"   // the preset's: gi_irradiance(x, n)
#include "gi/rsm_direct.glsl"
layout(location = 0) in vec2 uv;
uniform sampler2D g_albedo, g_normal, g_pos, ind, ind_n, ind_p;
layout(location = 0) out vec4 o_radiance;
layout(location = 1) out vec4 o_indirect;
layout(location = 2) out vec4 o_ldr;

bool same_surface(ivec2 q, vec3 x, vec3 n) {
    vec4 p = texelFetch(ind_p, q, 0);
    return p.w > 0.0 && dot(texelFetch(ind_n, q, 0).xyz, n) > 0.9 && abs(dot(p.xyz - x, n)) < 0.04;
}

vec3 upsampled_irradiance(vec3 x, vec3 n) {
    vec2 lo = (gl_FragCoord.xy - 0.5 - float(RSM_DIV / 2)) / float(RSM_DIV);  // low-res texel q sits at pixel q * DIV + DIV / 2
    ivec2 base = ivec2(floor(lo));
    vec2 f = lo - vec2(base);
    ivec2 size = textureSize(ind, 0);
    vec3 sum = vec3(0.0);
    float wsum = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            ivec2 q = clamp(base + ivec2(i, j), ivec2(0), size - 1);
            float w = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y) + 1e-4;
            if (same_surface(q, x, n)) { sum += w * texelFetch(ind, q, 0).rgb; wsum += w; }
        }
    if (wsum > 0.0) return sum / wsum;
    // None of the four: the same surface one low-res texel further out (thin strips along edges).
    // [[dont_unroll]]: unrolled, the 16 taps are straight-line code that llvmpipe runs (masked)
    // for every pixel, searching or not; as a loop it is skipped when no pixel of the SIMD group
    // needs it. The same taps in the same order: the same result, compose about 1.6x faster.
    [[dont_unroll]] for (int j = -1; j <= 2; ++j)
        [[dont_unroll]] for (int i = -1; i <= 2; ++i) {
            ivec2 q = clamp(base + ivec2(i, j), ivec2(0), size - 1);
            if (same_surface(q, x, n)) { sum += texelFetch(ind, q, 0).rgb; wsum += 1.0; }
        }
    return wsum > 0.0 ? sum / wsum : gi_irradiance(x, n);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(g_pos, px, 0);
    if (pos.w == 0.0) { o_radiance = vec4(0, 0, 0, 1); o_indirect = vec4(0, 0, 0, 1); o_ldr = vec4(0, 0, 0, 1); return; }
    vec3 n = normalize(texelFetch(g_normal, px, 0).xyz);
    vec3 albedo = texelFetch(g_albedo, px, 0).rgb;
    vec3 indirect = albedo / 3.14159265 * upsampled_irradiance(pos.xyz, n);
    vec3 radiance = rsm_direct(pos.xyz, n, albedo) + indirect;
    o_radiance = vec4(radiance, 1.0);
    o_indirect = vec4(indirect, 1.0);
    o_ldr = vec4(clamp(radiance * params.exposure, 0.0, 1.0), 1.0);
}
