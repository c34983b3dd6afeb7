#version 450
// Largest directional albedo over theta_o = 0..85 deg, per entry (energy), or only for the
// entries that claim to conserve energy (ENERGY_CONSERVING: Lambert, Cook-Torrance with the
// normalised Beckmann at both slopes, GGX with both visibility terms, Oren-Nayar,
// Ashikhmin-Shirley), x-th such entry in texel x. Energy conservation (000 L822-824):
// a(theta_o) <= 1 for every theta_o.
#include "entries.glsl"
layout(location = 0) out float energy;
uniform sampler2D albedo;
void main() {
#ifdef ENERGY_CONSERVING
    const int entries[7] = int[](0, 7, 8, 9, 10, 11, 12);
    int e = entries[int(gl_FragCoord.x)];
#else
    int e = int(gl_FragCoord.x);
#endif
    float a = 0.0;
    for (int x = 0; x < 18; ++x) a = max(a, texelFetch(albedo, ivec2(x, e), 0).r);
    energy = a;
}
