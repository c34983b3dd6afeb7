// Deterministic hemisphere sampling for numerical integration in shaders.
#ifndef PASSLAB_SAMPLING_GLSL
#define PASSLAB_SAMPLING_GLSL

// Point (i, j) of an n x n stratified grid over the hemisphere around +Z with a uniform
// solid-angle density: cos(theta) = u (uniform in [0, 1]), phi = 2 pi v; every sample stands
// for 2 pi / n^2 steradians.
vec3 hemisphere_uniform(int i, int j, int n) {
    float u = (float(i) + 0.5) / float(n), v = (float(j) + 0.5) / float(n);
    float cos_t = u, sin_t = sqrt(max(0.0, 1.0 - u * u)), phi = 6.28318530718 * v;
    return vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
}

// An orthonormal basis with `n` as its z axis (Frisvad 2012, with the n.z ~ -1 case handled).
mat3 basis_from_normal(vec3 n) {
    if (n.z < -0.9999999) return mat3(vec3(0, -1, 0), vec3(-1, 0, 0), n);
    float a = 1.0 / (1.0 + n.z), b = -n.x * n.y * a;
    return mat3(vec3(1.0 - n.x * n.x * a, b, -n.x), vec3(b, 1.0 - n.y * n.y * a, -n.y), n);
}

// Point (i, j) of an n x n stratified grid over the hemisphere around +Z with the cosine
// density cos(theta) / pi (Malley's method: uniform on the unit disk, lifted to the
// hemisphere): sin^2(theta) = u, phi = 2 pi v. Each of the n^2 directions carries the
// same weight, so an estimate is a plain count (000_c9f7e5de708ecbb3.txt L4880-4881: "apply cosine
// distribution around normal vector").
vec3 hemisphere_cosine(int i, int j, int n) {
    float u = (float(i) + 0.5) / float(n), v = (float(j) + 0.5) / float(n);
    float sin_t = sqrt(u), cos_t = sqrt(max(0.0, 1.0 - u)), phi = 6.28318530718 * v;
    return vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
}

#endif
