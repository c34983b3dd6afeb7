// Cascaded shadow maps, shared by cascaded-shadow-maps and sdsm (docs/catalogue.md 3.11).
// 000_c9f7e5de708ecbb3.txt L4709-4719: partition the view frustum, one cascade (shadow map) per
// sub-frustum, all in one layered depth image; cascades overlap for blending.
// 002_644d46bdce7e5305.txt L1867-1898 (SDSM): z-partitioning from the depth buffer's tight
// min/max, logarithmic; PSSM (L1874-1877) mixes log and uniform with a tuned lambda:
//     z_i = lambda * zmin (zmax / zmin)^(i / N) + (1 - lambda) * (zmin + (zmax - zmin) i / N)
// Buffer layout (std430), one record per cascade:
//     mat4 view_proj   the cascade's light matrix: a square sub-box of the light camera
//     vec4 range       (z_i - w_{i-1}, z_{i+1}, w_i, texel_world): view distances it covers,
//                      w_i = blend * (z_{i+1} - z_i) the band where cascade i blends into i + 1
#ifndef PASSLAB_SHADOWS_CASCADES_GLSL
#define PASSLAB_SHADOWS_CASCADES_GLSL

#define SHADOW_MAX_CASCADES 4

struct ShadowCascade {
    mat4 view_proj;
    vec4 range;
};

// The PSSM split distance i of n over [zmin, zmax] (lambda = 1: logarithmic, 0: uniform).
float shadow_split(int i, int n, float zmin, float zmax, float lambda) {
    float f = float(i) / float(n);
    return lambda * zmin * pow(zmax / zmin, f) + (1.0 - lambda) * (zmin + (zmax - zmin) * f);
}

#endif
