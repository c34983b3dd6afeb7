#version 450
// The texture to be compressed, generated at the texture's size into an rgba8 image (the
// uncompressed reference: 4 bytes per texel). Three sources:
//   picture:  smooth hue field, a noise marble, three overlapping hard-edged discs (junctions of
//             three colours inside one block, which BC1 cannot represent: its 4 colours lie on
//             one line in RGB), one-texel stripes and a row of fully transparent holes (alpha 0:
//             the encoder must use BC1's three-colour + transparent mode there)
//   gradient: c = mix(kFrom, kTo, s) with s a triangle wave along the diagonal: every colour of
//             the image lies on one segment in RGB, R and G rising while B falls (the case a
//             bounding-box encoder without its diagonal fix gets wrong)
//   flat:     every 4x4 block one random opaque colour (the one-colour round trip)
#include "common/hash.glsl"
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 texel;

const vec3 kFrom = vec3(0.05, 0.10, 0.95);   // gradient: the colour at s = 0
const vec3 kTo = vec3(0.95, 0.90, 0.05);     // and at s = 1
const float kGradientPeriod = 32.0;          // texels along x + y for s to go 0 -> 1 -> 0

vec3 hsv_to_rgb(vec3 c) {
    vec3 k = clamp(abs(fract(c.x + vec3(0.0, 2.0, 1.0) / 3.0) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
    return c.z * mix(vec3(1.0), k, c.y);
}

vec4 picture(vec2 p) {
    // Smooth field: hue along a diagonal, gently warped by noise.
    float warp = gradient_noise(vec3(p * 3.0, 0.5));
    vec3 c = hsv_to_rgb(vec3(0.55 * p.x + 0.3 * p.y + 0.1 * warp, 0.65, 0.95));
    // Marble patch (right, middle): bands of a noisy sine.
    vec2 m = p - vec2(0.78, 0.52);
    if (dot(m, m) < 0.035) {
        float n = 0.5 + 0.5 * sin(30.0 * p.x + 6.0 * gradient_noise(vec3(p * 6.0, 1.5)));
        c = mix(vec3(0.35, 0.12, 0.08), vec3(0.98, 0.92, 0.80), n);
    }
    // Three discs, hard edges, overlapping: regions of 3 different colours meet.
    const vec2 kDisc[3] = vec2[](vec2(0.26, 0.34), vec2(0.40, 0.34), vec2(0.33, 0.47));
    const vec3 kDiscColour[3] = vec3[](vec3(0.95, 0.10, 0.10), vec3(0.10, 0.85, 0.15), vec3(0.15, 0.25, 0.95));
    vec3 sum = vec3(0.0);
    int inside = 0;
    for (int i = 0; i < 3; ++i) {
        if (distance(p, kDisc[i]) < 0.12) { sum += kDiscColour[i]; ++inside; }
    }
    if (inside > 0) c = sum / float(inside);
    // One-texel stripes (bottom band): yellow / magenta / cyan, period 3 texels.
    ivec2 t = ivec2(gl_FragCoord.xy);
    if (p.y > 0.78 && p.y < 0.92 && p.x > 0.08 && p.x < 0.92) {
        int k = (t.x + t.y / 8) % 3;
        c = k == 0 ? vec3(1.0, 0.9, 0.1) : k == 1 ? vec3(0.9, 0.1, 0.8) : vec3(0.1, 0.8, 0.9);
    }
    // Transparent holes (top right): alpha 0 inside.
    float alpha = 1.0;
    for (int i = 0; i < 4; ++i) {
        if (distance(p, vec2(0.58 + 0.1 * float(i), 0.14)) < 0.035 + 0.005 * float(i)) alpha = 0.0;
    }
    return vec4(c, alpha);
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    if (params.source == SOURCE_GRADIENT) {
        float s = 1.0 - abs(1.0 - 2.0 * fract(float(t.x + t.y) / kGradientPeriod));
        texel = vec4(mix(kFrom, kTo, s), 1.0);
    } else if (params.source == SOURCE_FLAT) {
        texel = vec4(hash_pcg3(vec3(t / 4, 7.0)), 1.0);
    } else {
        texel = picture(uv);
    }
}
