#version 450
// Temporal adaptation (002_644d46bdce7e5305.txt L661-664):
//   previousLuminance = mix(previousLuminance, newLuminance, 1 - exp(-dt * 2.5))
// The rate depends on the frame time so the eye adapts at the same speed at any frame rate:
// n updates of dt compose to 1 - exp(-2.5 n dt). The first frame has no past: start at the mean.
layout(location = 0) in vec2 uv;
layout(location = 0) out float adapted;
uniform sampler2D lum;
uniform sampler2D adapted_prev;
void main() {
    float mean = textureLod(lum, vec2(0.5), 16.0).r;  // past the last level: the 1x1 one
    float prev = texelFetch(adapted_prev, ivec2(0), 0).r;
    adapted = frame.index == 0 ? mean : mix(prev, mean, frame.delta * params.rate);  // k per second
}
