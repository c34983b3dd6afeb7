#version 450
// The bokeh's widths (tests): over every texel of `blurred` brighter than half the peak, the
// spread of (p - centre) . u for u at 0, 60, 120 and 90 degrees:
//   width(u) = max - min + 1   (texels; + 1: each texel is one wide)
// A hexagon with vertices up and down (002's: its flats face 0, 60 and 120 degrees) has equal
// widths along 0/60/120 (flat to flat, sqrt(3) R) and 2R along 90: a ratio of 2/sqrt(3) = 1.155
// that a disc (1.0) would not have. Texel x of this 4 x 1 image holds direction x.
layout(location = 0) out float widths;
uniform sampler2D blurred;
const float kLevel = 0.5;  // fraction of the peak that counts as inside (half maximum)
void main() {
    ivec2 size = textureSize(blurred, 0);
    if (params.scene != SCENE_POINT) {  // a whole-image loop per texel: only for the kernel
        widths = 0.0;
        return;
    }
    float angle = radians(float[](0.0, 60.0, 120.0, 90.0)[int(gl_FragCoord.x)]);
    vec2 u = vec2(cos(angle), sin(angle));
    float peak = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) peak = max(peak, texelFetch(blurred, ivec2(x, y), 0).r);
    float lo = 1e9, hi = -1e9;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            if (texelFetch(blurred, ivec2(x, y), 0).r > kLevel * peak) {
                float t = dot(vec2(x, y) - vec2(size / 2), u);
                lo = min(lo, t), hi = max(hi, t);
            }
    widths = hi - lo + 1.0;
}
