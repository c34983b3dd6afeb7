// EXERCISE — 2D gradient noise (004_9a40ad89bdfc582a.txt L344-389): random gradients, not
// values, at the integer lattice; ramps through each corner, blended with a fade.
// Edit this file only (noise.frag and lattice.frag next to it are unchanged copies that make
// the preset's passes include your noise.glsl).
//     passlab run   procedural/gradient-noise --exercise presets/procedural/gradient-noise/exercise
//     passlab grade procedural/gradient-noise --exercise presets/procedural/gradient-noise/exercise
#include "common/hash.glsl"

// The random unit gradient g_ij at lattice point `cell`: done for you.
vec2 lattice_gradient(vec2 cell) {
    float a = 6.28318530718 * hash_pcg(vec3(cell, 7.0));
    return vec2(cos(a), sin(a));
}

float fade_curve(float t) {
    // TODO 1: the two blending functions of 004 L350-351:
    //     params.fade == FADE_QUINTIC:  q(t) = 6t^5 - 15t^4 + 10t^3   (C2: q''(0) = q''(1) = 0)
    //     otherwise (FADE_CUBIC):       h(t) = 3t^2 - 2t^3            (C1 only)
    // (Horner form keeps it cheap: t^3 (t (6t - 15) + 10).)
    return t;
}

float gradient_noise_2d(vec2 p) {
    vec2 i = floor(p), f = p - i;     // lattice corner (0, 0) of the cell, and P = (x, y) in it
    // TODO 2: the values of the four gradient ramps at P (004 L372): the ramp through corner
    // (a, b) is its gradient dotted with the vector from that corner to P, e.g.
    //     z10 = g10 . (x - 1, y)
    // with g_ab = lattice_gradient(i + vec2(a, b)).
    float z00 = 0.0, z10 = 0.0, z01 = 0.0, z11 = 0.0;
    vec2 u = vec2(fade_curve(f.x), fade_curve(f.y));
    // TODO 3: blend the ramps bilinearly with the fade as weights (004 L378-379):
    //     z_x0 = (1 - q(x)) z00 + q(x) z10,   z_x1 = (1 - q(x)) z01 + q(x) z11,
    //     z_xy = (1 - q(y)) z_x0 + q(y) z_x1
    // then scale: with unit gradients |z_xy| <= sqrt(2)/2 (reached at a cell centre), and the
    // preset wants n in [-1, 1], so return sqrt(2) z_xy.
    return 0.0;
}
