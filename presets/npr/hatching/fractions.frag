#version 450
// Test read-out of the bins. Per bin k of n.l: x = inked fraction, y = the bin's pixel count,
// z = its mean darkness 1 - tone, w = x - z (how far the ink misses the tone).
// STEPS: per k < 7, fraction(k + 1) - fraction(k), the step to the next brighter bin.
layout(location = 0) out vec4 result;
layout(std430) readonly buffer bins { uint counts[24]; };
const float kUnit = 4096.0;
float fraction(int k) { return float(counts[8 + k]) / max(float(counts[k]), 1.0); }
void main() {
    int k = int(gl_FragCoord.x);
#ifdef STEPS
    result = vec4(fraction(k + 1) - fraction(k), 0.0, 0.0, 1.0);
#else
    float darkness = float(counts[16 + k]) / kUnit / max(float(counts[k]), 1.0);
    result = vec4(fraction(k), float(counts[k]), darkness, fraction(k) - darkness);
#endif
}
