#version 450
// EXERCISE — TODO 4 (TODO 1, 2 in hex_gather.glsl, TODO 3 in hex_pass1.frag).
// Hexagonal blur pass 2 (002_644d46bdce7e5305.txt L1374-1398): A (up) blurred down-right gives
// one rhombus, B (up + down-right) blurred down-left gives the other two; the sum of the three
// normalised rhombi is divided by 3 — the "third pass" of the text (L1312) happens here in
// the code, whose own third pass is the fringe (hex_fringe.frag). 7 passes (3 rhombi x 2 blurs +
// combine) become 2.
// Where no tap contributes (in focus) A falls back to half of B's own colour (B = 2 x colour
// there), so the result is the colour again: (c + 2c) / 3.
#include "hex_gather.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blurred;
uniform sampler2D hexA;
uniform sampler2D hexB;
void main() {
    vec2 lInverseTextureSize = 1.0 / vec2(textureSize(hexA, 0));
    vec4 lBaseColor = texelFetch(hexB, ivec2(gl_FragCoord.xy), 0);  // = textureLod at the texel centre
    vec4 lColorA = vec4(vec3(0.0), lBaseColor.w), lColorB = lColorA;
    float lSampleCountA = 0.0, lSampleCountB = 0.0;
    vec2 lStepA = hex_step(kDownRight, lInverseTextureSize), lStepB = hex_step(kDownLeft, lInverseTextureSize);
    for (int i = 0; i < params.taps; i++) {
        float lStepDistance = (float(i) + 0.5) * lInverseTextureSize.y;
        lSampleCountA += doGatherAndApply(hexA, uv + (lStepA * lStepDistance), lBaseColor.w, lStepDistance, lInverseTextureSize, lColorA);
        lSampleCountB += doGatherAndApply(hexB, uv + (lStepB * lStepDistance), lBaseColor.w, lStepDistance, lInverseTextureSize, lColorB);
    }
    // TODO 4 (L1394-1396): normalise each 1D blur by the sum of its tap weights; where no tap
    // contributed (in focus) each falls back to its pixel's own value, expressed through B's
    // own colour lBaseColor (what does B hold there, after pass 1?). Then combine the three
    // normalised rhombi (A's one and B's two) into their average, in rgb.
    lColorA.xyz = (lSampleCountA > 0.0) ? (lColorA.xyz / lSampleCountA) : (lBaseColor.xyz * 0.5);
    lColorB.xyz = (lSampleCountB > 0.0) ? (lColorB.xyz / lSampleCountB) : lBaseColor.xyz;
    vec3 rgb = (lColorA.xyz + lColorB.xyz) / 3.0;
    blurred = vec4(rgb, max(abs(lColorA.w), abs(lColorB.w)));
}
