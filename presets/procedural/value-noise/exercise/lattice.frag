#version 450
// Pixel (x, y) of the 16x16 images stands for lattice point (x, y, 3): one target gets the hash
// there, the other the noise evaluated at exactly that point.
#include "noise.glsl"
layout(location = 0) out float hashed;
layout(location = 1) out float evaluated;
void main() {
    vec3 cell = vec3(floor(gl_FragCoord.xy), 3.0);
    hashed = 2.0 * lattice_value(cell) - 1.0;
    evaluated = value_noise_lab(cell);
}
