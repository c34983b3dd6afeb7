#version 450
// The bump presets' surface detail, made procedurally: a height field h in [0, 1] (rounded
// tiles with bevelled edges, plus shallow noise) and the tangent-space normal map derived from
// it (001_fe43b953f362fae7.txt L693-737):
//     N' = normalize(-h_u / k, -h_v / k, 1)     (h_u, h_v: central differences in uv units,
//                                                 1/k = params.bump_depth, the relief's depth)
// stored range-compressed, RGB = XYZ mapped [-1, 1] -> [0, 1] (001 L463-470). Alpha of the
// normal map holds the height, as 002's maps do (002_644d46bdce7e5305.txt L97-99).
// HEIGHT_KIND 0: tiles; 1: flat (h = 1 everywhere); 2: a step (h = 1 for u < 0.5, 0 after).
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 normal_map;

#ifndef HEIGHT_KIND
#define HEIGHT_KIND 0
#endif
const float kTiles = 4.0;

float height(vec2 t) {
#if HEIGHT_KIND == 1
    return 1.0;
#elif HEIGHT_KIND == 2
    return t.x < 0.5 ? 1.0 : 0.0;
#else
    vec2 f = fract(t * kTiles), e = min(f, 1.0 - f);
    float bevel = smoothstep(0.0, 0.08, min(e.x, e.y));
    return 0.85 * bevel + 0.15 * value_noise(vec3(t * 24.0, 1.0));
#endif
}

void main() {
    // The target's size: a fullscreen pass has uv = gl_FragCoord / size exactly.
    vec2 texel = uv / gl_FragCoord.xy;
    float h = height(uv);
    float hu = (height(uv + vec2(texel.x, 0.0)) - height(uv - vec2(texel.x, 0.0))) * 0.5 / texel.x;
    float hv = (height(uv + vec2(0.0, texel.y)) - height(uv - vec2(0.0, texel.y))) * 0.5 / texel.y;
    vec3 n = normalize(vec3(-hu * params.bump_depth, -hv * params.bump_depth, 1.0));
    normal_map = vec4(n * 0.5 + 0.5, h);
}
