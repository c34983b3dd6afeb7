#version 450
// The starburst modulation texture (002 L785-789): radial spokes of random strength, fading from
// the centre, as a function of the angle around the centre.
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 star;
const float kSpokes = 48.0;
void main() {
    vec2 d = uv - 0.5;
    float a = atan(d.y, d.x) / 6.28318 + 0.5;  // 0..1 around
    float cell = floor(a * kSpokes), f = fract(a * kSpokes);
    float s = mix(hash_pcg(vec3(cell, 1.0, 7.0)), hash_pcg(vec3(mod(cell + 1.0, kSpokes), 1.0, 7.0)), smoothstep(0.0, 1.0, f));
    float fade = clamp(1.0 - length(d) * 1.6, 0.0, 1.0);
    star = vec4(vec3(pow(s, 4.0) * fade), 1.0);
}
