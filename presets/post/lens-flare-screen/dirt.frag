#version 450
// The lens dirt modulation texture (002 L791-797): soft smudges over a faint fBm haze.
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 dirt;
void main() {
    vec3 p = vec3(uv * 6.0, 3.7);
    float haze = 0.5 * value_noise(p) + 0.25 * value_noise(p * 2.0) + 0.125 * value_noise(p * 4.0);
    float spots = smoothstep(0.62, 0.75, value_noise(vec3(uv * 18.0, 9.1)));
    dirt = vec4(vec3(0.15 * haze + 0.6 * spots), 1.0);
}
