#version 450
// EXERCISE — the prefiltered environment of the split sum (002_644d46bdce7e5305.txt L419-518,
// listing L444-518; Karis 2013). TODO 1-3 are in exercise/ibl.frag.
// For the direction R of this texel the lobe is assumed not to change shape with the view:
// N = V = R (002's prefilter has no view direction to use). GGX-importance-sampled half vectors
// H around N (importance_sample_ggx of passes/envmap/brdf_lut.glsl, in the frame `basis`) give
// light directions L; the average is weighted by n.l:
//     r += env(L) n.l;   w += n.l;   out = r / max(w, 1e-4)
// Level LEVEL holds roughness LEVEL / 5. Level 0, roughness 0, makes every H = N: L = R, the
// source itself.
#include "envmap/brdf_lut.glsl"
#include "envmap/cube.glsl"
#include "common/sampling.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 prefiltered;
uniform samplerCube env;
void main() {
    vec3 N = cube_face_direction(pl_iteration, uv), V = N;
    float roughness = float(LEVEL) / 5.0;
    mat3 basis = basis_from_normal(N);
    int n = LEVEL == 0 ? 1 : params.samples;
    vec3 r = vec3(0.0);
    float w = 0.0;
    for (int i = 0; i < n; ++i) {
        vec3 H = basis * importance_sample_ggx(hammersley(i, n), roughness);
        // TODO 4: the light direction L that H reflects the view direction V into (V points
        // from the surface towards the eye, reflect() wants the incident direction), and, for
        // the L above the surface, its contribution to r and w (formula above).
    }
    prefiltered = vec4(r / max(w, 1e-4), 1.0);
}
