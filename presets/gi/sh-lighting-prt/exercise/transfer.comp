#version 450
// Bake: the transfer vector of every vertex (000_c9f7e5de708ecbb3.txt L5420-5427): the
// directional visibility V(w), "computed as for AO", cosine-weighted and projected onto the 16
// SH basis functions,
//   T_k(P) = (1/pi) integral_{hemisphere(n)} V(w) max(n.w, 0) y_k(w) dw,
// so that the seed's I(P) = sum_i (rho/pi) L_in(w_i) V(w_i) cos(theta_i) dw, with
// L_in = sum_k L_k y_k, becomes rho * sum_k L_k T_k: one dot product per vertex at run time.
// The integral is estimated with an n x n stratified cosine-distributed grid (every direction
// carries pi / n^2 of the cosine integral, so T_k = (1/n^2) sum V y_k): with V = 1, T_0 is
// y_0 = 1 / (2 sqrt(pi)) exactly, whatever n.
// V is traced through the host's BVH (raytrace/bvh.glsl) against both meshes; with
// params.visibility off, V = 1 (the unshadowed transfer: plain SH irradiance).
layout(local_size_x = 64) in;
layout(std430) readonly buffer Verts { vec4 v[]; } verts;
layout(std430) writeonly buffer Transfer { float t[]; } transfer;  // 16 per vertex
#include "raytrace/bvh.glsl"
#include "common/sampling.glsl"
#include "gi/sh.glsl"
#include "env.glsl"

bool occluded(vec3 ro, vec3 rd) {
    for (uint mesh = 0u; mesh < 2u; ++mesh)
        if (pl_bvh_occluded(mesh, prt_object_from_world(mesh), ro, rd, 1e-4, 1e30)) return true;
    return false;
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= 2u * PRT_CAPACITY) return;
    vec3 p = verts.v[2u * i].xyz, n = verts.v[2u * i + 1u].xyz;
    float acc[16];
    for (int k = 0; k < 16; ++k) acc[k] = 0.0;
    if (dot(n, n) > 0.25) {  // slots past a mesh's vertex count were never written
        mat3 frame_n = basis_from_normal(n);
        int ns = params.transfer_samples;
        for (int a = 0; a < ns; ++a)
            for (int b = 0; b < ns; ++b) {
                // TODO 4 (000_c9f7e5de708ecbb3.txt L5420-5427): one direction of
                //   T_k = (1/pi) integral V(w) max(n.w, 0) y_k(w) dw
                // Take w = frame_n * hemisphere_cosine(a, b, ns) (cosine-distributed about n:
                // each direction carries pi / ns^2 of the cosine integral, so the 1/pi cancels
                // and T_k is the mean of V y_k); V = 0 when params.visibility is on and
                // occluded(p + 1e-3 * n, w); add y_k(w) (sh_eval(w, 4, y)) to acc[k] where V = 1.
            }
        for (int k = 0; k < 16; ++k) acc[k] /= float(ns * ns);
    }
    for (int k = 0; k < 16; ++k) transfer.t[16u * i + uint(k)] = acc[k];
}
