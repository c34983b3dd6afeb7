#version 450
// One texel of a half-resolution image = the mean of a 2x2 block, three ways
// (002_644d46bdce7e5305.txt L545-546, "you must believe in linear-space lighting", L616-617):
//   MODE_NAIVE  average the stored, gamma-encoded values as if they were light        (wrong)
//   MODE_GAMMA  decode pow(c, 2.2), average, encode pow(m, 1/2.2)  (002's shader route)
//   MODE_SRGB   sample the sRGB image at the block's centre with bilinear filtering: the sampler
//               decodes before it filters; the sRGB target encodes on store (002's GL_SRGB route)
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 down;
uniform sampler2D checker_unorm;
uniform sampler2D checker_srgb;

const float kGamma = 2.2;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;
#if defined(MODE_SRGB)
    // The block's centre is the corner shared by its 4 texels: one bilinear lookup = their mean.
    vec2 corner = vec2(p + 1) / vec2(textureSize(checker_srgb, 0));
    down = vec4(textureLod(checker_srgb, corner, 0.0).rgb, 1.0);
#else
    vec3 sum = vec3(0.0);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec3 c = texelFetch(checker_unorm, p + ivec2(x, y), 0).rgb;
#if defined(MODE_GAMMA)
            // (not decoded: the stored values are averaged as if they were light)
#endif
            sum += c;
        }
    vec3 m = sum / 4.0;
#if defined(MODE_GAMMA)
    m = pow(m, vec3(1.0 / kGamma));
#endif
    down = vec4(m, 1.0);
#endif
}
