#version 450
// EXERCISE — TODO 3 (TODO 1, 2 in hex_gather.glsl, TODO 4 in hex_pass2.frag).
// Hexagonal blur pass 1 (002_644d46bdce7e5305.txt L1340-1370): two 1D blurs at once into two
// targets (MRT): A = upwards, B = down-right (120 degrees from it) + A. Taps at (i + 0.5) pixels,
// i < params.taps (002: 8), one-sided: each is a skewed box from the pixel outwards.
// 002's text (L1310) says pass 1 blurs "down and left"; its code steps (+0.866, -0.5):
// down-*right* in its v-up coordinates. We follow the code; mirrored it is the same hexagon.
#include "hex_gather.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hexA;
layout(location = 1) out vec4 hexB;
uniform sampler2D src;
void main() {
    vec2 lInverseTextureSize = 1.0 / vec2(textureSize(src, 0));
    vec4 lBaseColor = texelFetch(src, ivec2(gl_FragCoord.xy), 0);  // = textureLod at the texel centre
    vec4 lOutputA = vec4(vec3(0.0), lBaseColor.w), lOutputB = lOutputA;
    float lSampleCountA = 0.0, lSampleCountB = 0.0;
    vec2 stepA = hex_step(kUp, lInverseTextureSize), stepB = hex_step(kDownRight, lInverseTextureSize);
    for (int i = 0; i < params.taps; i++) {
        float lStepDistance = (float(i) + 0.5) * lInverseTextureSize.y;
        lSampleCountA += doGatherAndApply(src, uv + stepA * lStepDistance, lBaseColor.w, lStepDistance, lInverseTextureSize, lOutputA);
        lSampleCountB += doGatherAndApply(src, uv + stepB * lStepDistance, lBaseColor.w, lStepDistance, lInverseTextureSize, lOutputB);
    }
    lOutputA.xyz = (lSampleCountA > 0.0) ? (lOutputA.xyz / lSampleCountA) : lBaseColor.xyz;
    lOutputB.xyz = (lSampleCountB > 0.0) ? (lOutputB.xyz / lSampleCountB) : lBaseColor.xyz;
    // TODO 3 (L1361-1363): B is written for pass 2 to blur down-left into TWO rhombi (the up one
    // and the down-right one). What must B hold besides its own down-right blur?
    if (abs(lOutputA.w) > abs(lOutputB.w)) lOutputB.w = lOutputA.w;
    hexA = lOutputA;
    hexB = lOutputB;
}
