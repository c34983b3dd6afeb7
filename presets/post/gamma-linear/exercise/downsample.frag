#version 450
// EXERCISE — averaging in linear light (002_644d46bdce7e5305.txt L543-622, "you must believe in
// linear-space lighting"). One texel of a half-resolution image = the mean of a 2x2 block of the
// checker, three ways (the preset compiles this file three times, with one MODE_ defined):
//   MODE_NAIVE  average the stored, gamma-encoded values as if they were light  (wrong, given)
//   MODE_GAMMA  002's shader route: decode, average, encode, with the 2.2 power law (TODO 1, 2)
//   MODE_SRGB   002's GL_SRGB route: let an sRGB image and an sRGB target do it  (TODO 3)
// Fill in the TODO blocks, then check your work against the reference:
//     passlab run   post/gamma-linear --exercise presets/post/gamma-linear/exercise   (live)
//     passlab grade post/gamma-linear --exercise presets/post/gamma-linear/exercise   (the cases)
// The third band of the picture is MODE_GAMMA, the fourth MODE_SRGB; squint: a right answer is as
// bright as the checker in the first band.
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 down;
uniform sampler2D checker_unorm;   // the checker's stored bytes, read as they are (UNORM, nearest)
uniform sampler2D checker_srgb;    // the same bytes in an sRGB image (bilinear filtering)

const float kGamma = 2.2;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) * 2;   // the block's first texel
#if defined(MODE_SRGB)
    // TODO 3: the sRGB route (002 L616 GL_TEXTURE_SRGB, L617 GL_FRAMEBUFFER_SRGB). Sampling
    // checker_srgb decodes each texel to linear light BEFORE the bilinear filter weights them,
    // and `down` is an sRGB target here: it encodes what you write when it stores it.
    // Get the mean of the block's 4 texels with ONE textureLod of checker_srgb (where do the 4
    // texels' bilinear weights become equal?) and write what the target should encode.
    down = vec4(0.0, 0.0, 0.0, 1.0);
#else
    vec3 sum = vec3(0.0);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            vec3 c = texelFetch(checker_unorm, p + ivec2(x, y), 0).rgb;
#if defined(MODE_GAMMA)
            // TODO 1: c is a stored value v, the monitor shows it as light v^2.2 (002 L572-574,
            // L616). Turn it into light before it is added, with the power law and kGamma
            // (this route is 002's pow(), not the piecewise sRGB curve of common/color.glsl).
#endif
            sum += c;
        }
    vec3 m = sum / 4.0;
#if defined(MODE_GAMMA)
    // TODO 2: m is now light, but `down` is a UNORM target that stores what you write: encode
    // it for the monitor with the inverse power law (002 L617).
#endif
    down = vec4(m, 1.0);
#endif
}
