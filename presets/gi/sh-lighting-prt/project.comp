#version 450
// The environment projected onto the first 4 bands (16 coefficients, 000 L5412-5416), every
// frame (the lighting is what PRT lets change):
//   L_k = integral_sphere L(w) y_k(w) dw
// by a product rule: Gauss-Legendre in cos(theta) (64 nodes, exact for polynomials of degree
// < 128) times a uniform grid in phi (128 steps, exact for cos(m phi), |m| < 128). One work
// group: thread i integrates node i over phi, then 16 threads sum the 64 partial rows in a fixed
// order (deterministic).
// params.rotate: "sh" projects the unrotated environment and rotates the coefficients by
// params.env_yaw in the SH domain (sh_rotate_polar); "reproject" projects the rotated
// environment. The two must agree (the rotation test).
layout(local_size_x = 64) in;
layout(std430) writeonly buffer EnvSh { vec4 c[16]; } env_sh;  // rgb per coefficient
#include "gi/sh.glsl"
#include "env.glsl"

const int NZ = 64, NPHI = 128;
shared vec3 partial[NZ][16];
shared vec3 total[16];

void main() {
    int i = int(gl_LocalInvocationID.x);
    float z, wz;
    sh_gauss_legendre(i, NZ, z, wz);
    vec3 acc[16];
    for (int k = 0; k < 16; ++k) acc[k] = vec3(0.0);
    float dphi = 2.0 * SH_PI / float(NPHI);
    for (int j = 0; j < NPHI; ++j) {
        vec3 w = sh_direction(z, (float(j) + 0.5) * dphi);
        vec3 L = params.rotate == ROTATE_SH ? env_radiance_fixed(w) : env_radiance(w);
        float y[16];
        sh_eval(w, 4, y);
        for (int k = 0; k < 16; ++k) acc[k] += L * y[k];
    }
    for (int k = 0; k < 16; ++k) partial[i][k] = acc[k] * (wz * dphi);
    barrier();
    if (i < 16) {
        vec3 s = vec3(0.0);
        for (int r = 0; r < NZ; ++r) s += partial[r][i];
        total[i] = s;
    }
    barrier();
    if (i == 0) {
        vec3 c[16];
        for (int k = 0; k < 16; ++k) c[k] = total[k];
        if (params.rotate == ROTATE_SH) sh_rotate_polar(c, 4, radians(params.env_yaw));
        for (int k = 0; k < 16; ++k) env_sh.c[k] = vec4(c[k], 0.0);
    }
}
