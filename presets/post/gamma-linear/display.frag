#version 450
// Four bands, as display values: the full-resolution checker (the eye averages it in light),
// then the three half-resolution results. Squint: the right answer matches the checker.
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D checker_unorm;
uniform sampler2D down_naive;
uniform sampler2D down_gamma;
uniform sampler2D down_srgb;
void main() {
    int band = int(uv.x * 4.0);
    vec3 c = band == 0   ? texelFetch(checker_unorm, ivec2(gl_FragCoord.xy), 0).rgb
             : band == 1 ? texture(down_naive, uv).rgb
             : band == 2 ? texture(down_gamma, uv).rgb
                         : linear_to_srgb(texture(down_srgb, uv).rgb);  // sampled decoded: encode back
    ldr = vec4(c, 1.0);
}
