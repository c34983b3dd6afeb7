// Real spherical harmonics, bands 0..2 (9 functions), in the real form of 002_644d46bdce7e5305.txt
// L2512-2516 (y_l^m = sqrt(2) K_l^m cos/sin(|m| phi) P_l^|m|(cos theta), K_l^m the normalisation),
// written out in Cartesian form for a unit direction d; and the clamped-cosine convolution that
// turns radiance SH into irradiance (Ramamoorthi & Hanrahan 2001: A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4).
#ifndef PASSLAB_GI_TETRAHEDRAL_SH_GLSL
#define PASSLAB_GI_TETRAHEDRAL_SH_GLSL

void tetrahedral_sh9(vec3 d, out float y[9]) {
    y[0] = 0.282095;                                   // K_0^0
    y[1] = 0.488603 * d.y;                             // l = 1: sqrt(3 / 4 pi) (y, z, x)
    y[2] = 0.488603 * d.z;
    y[3] = 0.488603 * d.x;
    y[4] = 1.092548 * d.x * d.y;                       // l = 2
    y[5] = 1.092548 * d.y * d.z;
    y[6] = 0.315392 * (3.0 * d.z * d.z - 1.0);
    y[7] = 1.092548 * d.x * d.z;
    y[8] = 0.546274 * (d.x * d.x - d.y * d.y);
}

float tetrahedral_sh_band_factor(int i) { return i == 0 ? 3.14159265 : (i < 4 ? 2.0943951 : 0.7853982); }

#endif
