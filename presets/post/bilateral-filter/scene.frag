#version 450
// The input: a few shaded spheres in front of a wall with per-pixel noise (as from a noisy
// effect such as SSAO or few-sample lighting), and its depth as the guide. Or test patterns.
// The guide (the range channel of the joint filter) rides in the colour's alpha, so one fetch
// per tap reads both (on lavapipe a second texture fetch per tap nearly tripled the filter's cost).
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    float n = params.noise * (hash_pcg(vec3(gl_FragCoord.xy, 5.0)) - 0.5);
    if (params.scene == SCENE_CONSTANT) {
        color = vec4(vec3(0.5 + n), 1.0);  // noise 0: exactly constant; guide (alpha) 1
        return;
    }
    if (params.scene == SCENE_STEP) {
        bool right = gl_FragCoord.x >= 32.0;
        color = vec4(vec3(right ? 1.0 : 0.0), right ? 2.0 : 1.0);  // guide (alpha) 1 | 2
        return;
    }
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0);
    vec3 c = vec3(0.35, 0.33, 0.3) + 0.1 * uv.y;  // the wall, depth 5
    float d = 5.0;
    for (int i = 0; i < 3; ++i) {
        vec2 center = vec2(-0.45 + 0.45 * float(i), 0.05 * float(i - 1));
        float r = 0.18 + 0.03 * float(i), q = length(p - center);
        if (q < r) {
            vec3 nrm = vec3((p - center) / r, sqrt(max(0.0, 1.0 - q * q / (r * r))));
            vec3 base = i == 0 ? vec3(0.9, 0.4, 0.3) : i == 1 ? vec3(0.3, 0.8, 0.4) : vec3(0.3, 0.5, 0.9);
            c = base * (0.2 + 0.8 * max(dot(nrm, normalize(vec3(-0.4, -0.5, 0.8))), 0.0));
            d = 2.0 + float(i) - nrm.z * r;
        }
    }
    color = vec4(c + n, d);  // alpha: the guide, view depth
}
