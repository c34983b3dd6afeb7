// EXERCISE — value noise (004_9a40ad89bdfc582a.txt L306-311): random values at the integer
// lattice, interpolated inside each cell. This file shadows the preset's noise.glsl, which both
// noise.frag (the image) and lattice.frag (the lattice check) include.
//     passlab run   procedural/value-noise --exercise presets/procedural/value-noise/exercise
//     passlab grade procedural/value-noise --exercise presets/procedural/value-noise/exercise
// lattice_value is done for you; fill in the three TODO blocks of value_noise_lab.
#include "common/hash.glsl"

// The random value in [0, 1) at lattice point `cell` (integer coordinates).
float lattice_value(vec3 cell) {
    if (params.hash == HASH_SIN) {
        // The notes' hash: n = dot(floor(p), (1, 57, 113)) then fract(sin(n) * 43758.5453).
        float n = dot(cell, vec3(1.0, 57.0, 113.0));
        return fract(sin(n) * 43758.5453123);
    }
    return hash_pcg(cell);
}

float value_noise_lab(vec3 p) {
    vec3 i = floor(p);     // the cell's lower corner
    vec3 f = fract(p);     // where p is inside the cell, each component in [0, 1)
    // TODO 1: the interpolation weights w from f. "Linearly isn't sufficient" (004 L311): with
    // params.fade == FADE_CUBIC use the fade h(t) = 3t^2 - 2t^3 of 002_644d46bdce7e5305.txt
    // L2385, per component; otherwise (FADE_LINEAR) the weights are f itself.
    vec3 w = vec3(0.0);
    float n000 = lattice_value(i), n100 = lattice_value(i + vec3(1, 0, 0));
    float n010 = lattice_value(i + vec3(0, 1, 0)), n110 = lattice_value(i + vec3(1, 1, 0));
    float n001 = lattice_value(i + vec3(0, 0, 1)), n101 = lattice_value(i + vec3(1, 0, 1));
    float n011 = lattice_value(i + vec3(0, 1, 1)), n111 = lattice_value(i + vec3(1, 1, 1));
    // TODO 2: blend the eight corner values trilinearly with the weights w: along x first (four
    // mix()es, each between two corners that differ only in x), then those four along y, then
    // the two along z. 002 L2389 is the same nest of mix() calls on its sin-hashed corners.
    float v = n000;
    // TODO 3: v is in [0, 1]; the noise is wanted in [-1, 1] (004 L306) so that its mean is 0.
    return v;
}
