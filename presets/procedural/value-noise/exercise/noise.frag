#version 450
#include "noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float n;
void main() {
    // params.cells lattice cells per image height; the z slice is between lattice planes.
    vec2 p = gl_FragCoord.xy / frame.resolution.y * params.cells;
    n = value_noise_lab(vec3(p, params.z));
}
