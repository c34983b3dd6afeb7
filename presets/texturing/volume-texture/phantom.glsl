// The volume's content, a procedural "scan" (000_c9f7e5de708ecbb3.txt L1762-1768: "3D voxel
// array of texture values, explicit sampled function, e.g. from medical scanners (CT, MRT)"):
// a head-like phantom of ellipsoids, in the spirit of Shepp and Logan, over [-1, 1]^3.
// Density: shell 0.5, interior 0.2, two "ventricles" 0 and three lesions 0.8-1.0 (as if
// contrast-enhanced: denser than the shell, so no value interpolated between shell, tissue and
// air reaches a lesion's), plus a faint noise texture in the interior.
#ifndef VOLUME_PHANTOM_GLSL
#define VOLUME_PHANTOM_GLSL
#include "common/noise.glsl"

bool in_ellipsoid(vec3 p, vec3 c, vec3 r) { vec3 q = (p - c) / r; return dot(q, q) <= 1.0; }

float phantom(vec3 p) {
    if (!in_ellipsoid(p, vec3(0.0), vec3(0.72, 0.9, 0.8))) return 0.0;
    if (!in_ellipsoid(p, vec3(0.0, -0.02, 0.0), vec3(0.66, 0.84, 0.74))) return 0.5;   // shell
    float d = 0.2 + 0.06 * (value_noise(p * 6.0) - 0.5);
    if (in_ellipsoid(p, vec3(-0.2, 0.1, 0.0), vec3(0.1, 0.3, 0.2)) ||
        in_ellipsoid(p, vec3(0.2, 0.1, 0.0), vec3(0.1, 0.3, 0.2))) d = 0.0;         // ventricles
    if (in_ellipsoid(p, vec3(0.0, -0.45, 0.25), vec3(0.12))) d = 1.0;              // lesions
    if (in_ellipsoid(p, vec3(0.3, -0.2, -0.35), vec3(0.08, 0.1, 0.08))) d = 0.9;
    if (in_ellipsoid(p, vec3(-0.35, -0.35, -0.2), vec3(0.06))) d = 0.8;
    return d;
}

// Voxel (i, j, k) of an N^3 grid covers [-1, 1]^3; its centre in texture coordinates is
// (ijk + 0.5) / N and in the volume's space:
vec3 voxel_centre(ivec3 ijk, int n) { return (vec3(ijk) + 0.5) / float(n) * 2.0 - 1.0; }
#endif
