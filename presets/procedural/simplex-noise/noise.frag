#version 450
// Simplex noise (passes/common/noise.glsl, 004_9a40ad89bdfc582a.txt L391-443), one octave or a
// fractal sum of octaves (each twice the frequency and half the amplitude, normalised by the sum
// of amplitudes so the range stays [-1, 1]).
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float field;
void main() {
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0) * params.frequency;
    float sum = 0.0, amp = 1.0, norm = 0.0;
    for (int i = 0; i < params.octaves; ++i) {
        sum += amp * simplex_noise(p + float(i) * vec2(17.3, 4.1));
        norm += amp;
        amp *= 0.5;
        p *= 2.0;
    }
    field = sum / norm;
}
