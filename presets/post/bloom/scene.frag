#version 450
// A dark room with glowing lamps (radiance params.emission) and dim walls, or one bright
// 16x16 square in the middle of black (aligned to 4x4 blocks, for the energy test; square_offset:
// moved by (2, 1) pixels, so the bright pass's 4x4 blocks cut it at every side).
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
void main() {
    vec2 p = gl_FragCoord.xy, c = frame.resolution.xy * 0.5;
    if (params.scene == SCENE_SQUARE || params.scene == SCENE_SQUARE_OFFSET) {
        if (params.scene == SCENE_SQUARE_OFFSET) c += vec2(2.0, 1.0);
        bool in_square = all(greaterThanEqual(p, c - 8.0)) && all(lessThan(p, c + 8.0));
        hdr = vec4(vec3(in_square ? params.emission : 0.0), 1.0);
        return;
    }
    vec2 q = uv * vec2(frame.aspect, 1.0);
    vec3 col = mix(vec3(0.05, 0.045, 0.06), vec3(0.16, 0.12, 0.1), smoothstep(0.55, 0.6, uv.y));  // wall, floor
    // A row of lamps of different sizes and tints, and a window slit.
    for (int i = 0; i < 5; ++i) {
        vec2 at = vec2(0.25 + 0.34 * float(i), 0.32 + 0.05 * sin(float(i) * 2.1));
        float r = 0.02 + 0.015 * hash_pcg(vec3(float(i), 3.0, 1.0));
        vec3 tint = mix(vec3(1.0, 0.75, 0.45), vec3(0.6, 0.8, 1.0), hash_pcg(vec3(float(i), 5.0, 2.0)));
        if (length(q - at) < r) col = tint * params.emission;
    }
    if (abs(q.x - 1.5) < 0.01 && uv.y > 0.62 && uv.y < 0.9) col = vec3(params.emission * 0.5);
    hdr = vec4(col, 1.0);
}
