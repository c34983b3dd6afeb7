#version 450
// FXAA (Lottes 2009, "FXAA 3.11" quality path), named in 002_644d46bdce7e5305.txt L1852 among
// Supraleiter's anti-aliasing modes (L1850-1857). One pass on the final image, per pixel:
// 1. Local contrast: range = max - min of the luma of the pixel and its 4 neighbours; below
//    max(EDGE_THRESHOLD_MIN, EDGE_THRESHOLD x max) the pixel is returned as it is (no edge).
// 2. Sub-pixel aliasing: the 3x3 low-pass luma (weights 2 for N S E W, 1 for the corners, / 12)
//    against the pixel's: a one-pixel feature gets blended by up to SUBPIX (smoothstep)^2.
// 3. Edge orientation from the 3x3 second differences: horizontal if the vertical ones dominate;
//    the side (N or S, W or E) with the larger gradient is where the edge lies.
// 4. Walk both ways along the edge, half a pixel towards that side, until the mean luma of the
//    two rows (columns) differs from the local average by more than gradient / 4: the ends.
// 5. The pixel's offset towards the edge: 0.5 - (distance to the nearer end) / (span length),
//    if that end's luma turns the right way (the edge really bends towards this pixel); then
//    one bilinear fetch at the offset position.
// Reads `color` (linear filtering, clamp), writes `fxaa`. Luma: passes/aa/luma.glsl.
// Deviation (stated): FXAA 3.11 expects the luma precomputed in alpha and filters *luma* in the
// edge-end search; here the search takes the luma of the filtered colour (luma_uv), which
// differs where the search position falls between texels of different colour (the luma is
// non-linear: sRGB-encoded). The early exit, sub-pixel term and orientation read whole texels
// and are unaffected.
#include "aa/luma.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 fxaa;
uniform sampler2D color;
const float EDGE_THRESHOLD = 0.166;       // FXAA 3.11 "quality" default (0.125 .. 0.333)
const float EDGE_THRESHOLD_MIN = 0.0833;  // ignore dark edges below this
const float SUBPIX = 0.75;                // amount of sub-pixel aliasing removal
const int kSteps = 12;
const float kStep[kSteps] = float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);  // FXAA_QUALITY 29

float luma_uv(vec2 p) { return aa_luma(textureLod(color, p, 0.0).rgb); }
float luma_px(ivec2 p, ivec2 last) { return aa_luma(texelFetch(color, clamp(p, ivec2(0), last), 0).rgb); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(color, 0) - 1;
    vec2 texel = 1.0 / vec2(textureSize(color, 0));
    vec2 posM = (vec2(p) + 0.5) * texel;
    vec4 rgbM = texelFetch(color, p, 0);
    float lumaM = aa_luma(rgbM.rgb);
    float lumaN = luma_px(p + ivec2(0, -1), last), lumaS = luma_px(p + ivec2(0, 1), last);
    float lumaW = luma_px(p + ivec2(-1, 0), last), lumaE = luma_px(p + ivec2(1, 0), last);
    float rangeMax = max(max(max(lumaN, lumaS), max(lumaW, lumaE)), lumaM);
    float rangeMin = min(min(min(lumaN, lumaS), min(lumaW, lumaE)), lumaM);
    float range = rangeMax - rangeMin;
    if (range < max(EDGE_THRESHOLD_MIN, rangeMax * EDGE_THRESHOLD)) {  // 1. no edge: unchanged
        fxaa = rgbM;
        return;
    }
    float lumaNW = luma_px(p + ivec2(-1, -1), last), lumaNE = luma_px(p + ivec2(1, -1), last);
    float lumaSW = luma_px(p + ivec2(-1, 1), last), lumaSE = luma_px(p + ivec2(1, 1), last);
    // 2. Sub-pixel blend amount.
    float subpixA = 2.0 * (lumaN + lumaS + lumaW + lumaE) + (lumaNW + lumaNE + lumaSW + lumaSE);
    float subpixC = clamp(abs(subpixA / 12.0 - lumaM) / range, 0.0, 1.0);
    float subpixD = (-2.0 * subpixC + 3.0) * subpixC * subpixC;
    float subpixH = subpixD * subpixD * SUBPIX;
    // 3. Orientation and side.
    float edgeHorz = abs(-2.0 * lumaW + lumaNW + lumaSW) + 2.0 * abs(-2.0 * lumaM + lumaN + lumaS) + abs(-2.0 * lumaE + lumaNE + lumaSE);
    float edgeVert = abs(-2.0 * lumaN + lumaNW + lumaNE) + 2.0 * abs(-2.0 * lumaM + lumaW + lumaE) + abs(-2.0 * lumaS + lumaSW + lumaSE);
    bool horzSpan = edgeHorz >= edgeVert;
    float lengthSign = horzSpan ? texel.y : texel.x;
    if (!horzSpan) lumaN = lumaW, lumaS = lumaE;
    float gradientN = abs(lumaN - lumaM), gradientS = abs(lumaS - lumaM);
    bool pairN = gradientN >= gradientS;
    float gradient = max(gradientN, gradientS);
    if (pairN) lengthSign = -lengthSign;
    float lumaNN = (pairN ? lumaN : lumaS) + lumaM;  // twice the mean across the edge
    // 4. Search both ways along the edge, half a pixel towards it.
    vec2 posB = posM;
    if (horzSpan) posB.y += 0.5 * lengthSign; else posB.x += 0.5 * lengthSign;
    vec2 offNP = horzSpan ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 posN = posB - offNP * kStep[0], posP = posB + offNP * kStep[0];
    float gradientScaled = gradient * 0.25;
    float lumaEndN = luma_uv(posN) - 0.5 * lumaNN, lumaEndP = luma_uv(posP) - 0.5 * lumaNN;
    bool doneN = abs(lumaEndN) >= gradientScaled, doneP = abs(lumaEndP) >= gradientScaled;
    for (int i = 1; i < kSteps && !(doneN && doneP); ++i) {
        if (!doneN) posN -= offNP * kStep[i], lumaEndN = luma_uv(posN) - 0.5 * lumaNN, doneN = abs(lumaEndN) >= gradientScaled;
        if (!doneP) posP += offNP * kStep[i], lumaEndP = luma_uv(posP) - 0.5 * lumaNN, doneP = abs(lumaEndP) >= gradientScaled;
    }
    // 5. Offset from the nearer end, if the edge turns towards this pixel there.
    float dstN = horzSpan ? posM.x - posN.x : posM.y - posN.y;
    float dstP = horzSpan ? posP.x - posM.x : posP.y - posM.y;
    bool lumaMLTZero = lumaM - 0.5 * lumaNN < 0.0;
    bool goodSpan = (dstN < dstP) ? ((lumaEndN < 0.0) != lumaMLTZero) : ((lumaEndP < 0.0) != lumaMLTZero);
    float pixelOffset = 0.5 - min(dstN, dstP) / (dstN + dstP);
    float offset = max(goodSpan ? pixelOffset : 0.0, subpixH);
    vec2 pos = posM;
    if (horzSpan) pos.y += offset * lengthSign; else pos.x += offset * lengthSign;
    fxaa = vec4(textureLod(color, pos, 0.0).rgb, rgbM.a);
}
