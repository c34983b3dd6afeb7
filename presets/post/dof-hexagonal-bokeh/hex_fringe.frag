#version 450
// 002's pass 3 (002_644d46bdce7e5305.txt L1402-1424): where the blur is more than 0.001 of the
// height (factor ramps over 0.001..0.002), mix from the sharp image to the blurred one, whose
// red, green and blue are fetched fringe = 0.7 pixels apart along the three hexagon directions
// (chromatic aberration of the bokeh's rim). The printed uTexSourceA is read here as the sharp
// source: where the factor is 0 the output is A, which must be the in-focus image.
// resolution = half (not 002's): `blurred` is view/2; it is read bilinearly at this pixel's uv
// (the upsample), and the fringe offsets stay in view pixels (the sharp source's texel size).
#include "hex_gather.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D src;
uniform sampler2D blurred;
void main() {
    float lFringe = params.fringe;  // 002: 0.7
    vec2 lInverseTextureSize = 1.0 / vec2(textureSize(src, 0));  // view pixels (= blurred's at full resolution)
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 lColorA = texelFetch(src, p, 0);
    vec4 lColorB = params.resolution == RESOLUTION_HALF ? textureLod(blurred, uv, 0.0) : texelFetch(blurred, p, 0);
    float lFactor = clamp(1000.0 * (abs(lColorB.w) - 0.001), 0.0, 1.0);
    vec2 o = lInverseTextureSize * lFringe * lFactor;
    result = (lFactor < 1e-6) ? lColorA
                              : mix(lColorA,
                                    vec4(textureLod(blurred, uv + kUp * o, 0.0).x, textureLod(blurred, uv + kDownLeft * o, 0.0).y,
                                         textureLod(blurred, uv + kDownRight * o, 0.0).z, lColorA.w),
                                    lFactor);
}
