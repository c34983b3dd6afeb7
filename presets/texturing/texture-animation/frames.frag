#version 450
// The "video": N frames of a looping animation baked into the layers of a 2D-array texture
// (repeat = N, one layer per iteration). Frame k: rings spreading from three drops, phase
// k / N, so frame N would equal frame 0 — the loop has no jump.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
#include "animation.glsl"   // kTwoPi
void main() {
    float phase = float(pl_iteration) / float(pl_iteration_count);
    const vec2 kDrops[3] = vec2[](vec2(0.3, 0.35), vec2(0.7, 0.6), vec2(0.45, 0.8));
    float h = 0.0;
    for (int i = 0; i < 3; ++i) {
        // distance on the torus (the texture repeats), rings moving outwards with the phase
        vec2 d = abs(uv - kDrops[i]);
        d = min(d, 1.0 - d);
        h += 0.5 + 0.5 * cos(kTwoPi * (6.0 * length(d) - phase - float(i) / 3.0));
    }
    h /= 3.0;
    color = vec4(mix(vec3(0.05, 0.2, 0.35), vec3(0.6, 0.85, 0.95), h), 1.0);
}
