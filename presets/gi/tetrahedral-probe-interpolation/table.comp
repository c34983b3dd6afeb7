#version 450
// The probes' irradiance for every surface normal of the box, E_k,s = sum_i A_l(i) c_k,i y_i(n_s):
// the walls and block faces are flat, so a fragment's normal is one of 18 (the surfaces of
// gi/radiosity_patches.glsl). Blending is linear, so blending these four numbers with the
// barycentric weights equals blending the four SHs and evaluating the result (show.frag does
// either; the test `table-equals-sh` checks they agree); it is 4 loads a fragment instead of 36,
// which on lavapipe is the difference between ~25 and ~70 ms a frame. A moving object, whose
// normals are not known in advance, needs the SH path (`path = sh`).
layout(local_size_x = 64) in;

#define TP_LOOKUP 1
#include "gi/tetrahedral_probes.glsl"
#include "gi/tetrahedral_sh.glsl"
#include "gi/radiosity_patches.glsl"

layout(std430) writeonly buffer Table { vec4 e[]; } table;

void main() {
    int t = int(gl_GlobalInvocationID.x);
    if (t >= TP_PROBES * TP_SURFACES) return;
    int k = t / TP_SURFACES, s = t % TP_SURFACES;
    float y[9];
    tetrahedral_sh9(radiosity_world_normal(radiosity_surface(s)), y);
    vec3 e = vec3(0.0);
    for (int i = 0; i < TP_SH; ++i) e += tetrahedral_sh_band_factor(i) * probes.coeff[k * TP_SH + i].rgb * y[i];
    table.e[t] = vec4(e, 0.0);
}
