#version 450
// Every visible point of the box lit by the probes: locate its tetrahedron, blend the four probes'
// SH with the barycentric weights (L2814), turn radiance SH into irradiance along the normal
// (E(n) = sum_i A_l(i) c_i y_i(n)) and reflect it diffusely, L = (rho / pi) E: the first indirect
// bounce. With `path = table` (default) the four probes' irradiance for this surface's normal is
// blended instead (table.comp; equal by linearity, 4 loads instead of 36). Target 1 gets the raw
// barycentric weights and target 2 their sum - 1, so the tests check the weights this very shader
// used (compiled with WRITE_WEIGHTS = 1 in the test-only passes). The path is a define, not a
// branch on the param: on lavapipe the untaken SH branch still cost about a third of the frame.
#define TP_LOOKUP 1
#define TP_TABLE 1
#include "gi/tetrahedral_probes.glsl"
#include "gi/tetrahedral_sh.glsl"
#include "gi/radiosity_patches.glsl"

layout(location = 0) in vec3 object_pos;
layout(location = 1) flat in int instance;
layout(location = 2) in vec3 world_pos;
layout(location = 3) in vec3 world_normal;
layout(location = 0) out vec4 color;
#if WRITE_WEIGHTS
layout(location = 1) out vec4 out_weights;
layout(location = 2) out float out_sum;
#endif

void main() {
    vec3 x = world_pos, n = normalize(world_normal);
    int tet;
    vec4 w;
    tetrahedral_locate(x, tet, w);
    vec3 e = vec3(0.0);
    ivec4 v = tets.rec[5 * tet];
    vec4 wn = max(w, 0.0) / dot(max(w, 0.0), vec4(1.0));
#if TP_SH_PATH
    float y[9];
    tetrahedral_sh9(n, y);
    for (int i = 0; i < TP_SH; ++i) e += tetrahedral_sh_band_factor(i) * tetrahedral_blend(v, wn, i) * y[i];
#else
    e = tetrahedral_blend_table(v, wn, radiosity_surface_of_hit(MESH, instance, object_pos));
#endif
    vec3 l = cornell_albedo(MESH, instance) / 3.14159265 * max(e, 0.0);
    if (params.show == SHOW_WEIGHTS) l = w.yzw;  // the barycentric weights as a colour
    color = vec4(l * (params.show == SHOW_WEIGHTS ? 1.0 : params.exposure), 1.0);
#if WRITE_WEIGHTS
    out_weights = w;
    out_sum = w.x + w.y + w.z + w.w - 1.0;
#endif
}
