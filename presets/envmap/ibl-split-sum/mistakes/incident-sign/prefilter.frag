#version 450
// The prefiltered environment of the split sum (002_644d46bdce7e5305.txt L419-518, listing L444-518; Karis 2013):
// for the direction R of this texel, with N = V = R (the lobe assumed not to change shape with
// the view), GGX-importance-sampled half vectors H around N and L = reflect(-V, H):
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
        vec3 L = reflect(V, H);
        float nl = dot(N, L);
        if (nl > 0.0) r += textureLod(env, L, 0.0).rgb * nl, w += nl;
    }
    prefiltered = vec4(r / max(w, 1e-4), 1.0);
}
