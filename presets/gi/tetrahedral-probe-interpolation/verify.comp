#version 450
// The lookup of gi/tetrahedral_probes.glsl, the one show.frag uses, checked where the answer is
// known. Threads 0 .. TP_PROBES - 1: at probe i's own position the blend must return probe i's SH
// exactly, and the table path's blend its irradiance for every surface (max |difference| over
// those 27 + 54 numbers into exact[i]). Threads TP_PROBES ..: random
// points of the lattice, 1 in 8 snapped onto a cell face, edge or corner (where tetrahedra meet
// and rounding decides), write their raw weights and weights - sum to `samples`.
layout(local_size_x = 64) in;

#define TP_LOOKUP 1
#define TP_TABLE 1
#include "gi/tetrahedral_probes.glsl"
#include "common/hash.glsl"

layout(std430) writeonly buffer Exact { float diff[]; } exact;
layout(std430) writeonly buffer Samples { vec4 w[]; } samples;  // 2 per point: weights, (sum - 1, tet, 0, 0)

const int TP_SAMPLES = 4096;

void main() {
    int t = int(gl_GlobalInvocationID.x);
    int tet;
    vec4 w;
    if (t < TP_PROBES) {
        tetrahedral_locate(tetrahedral_probe_position(t), tet, w);
        float d = 0.0;
        for (int i = 0; i < TP_SH; ++i) d = max(d, length(tetrahedral_coeff(tet, w, i) - probes.coeff[t * TP_SH + i].rgb));
        vec4 wn = max(w, 0.0) / dot(max(w, 0.0), vec4(1.0));
        for (int s = 0; s < TP_SURFACES; ++s)
            d = max(d, length(tetrahedral_blend_table(tets.rec[5 * tet], wn, s) - table.e[t * TP_SURFACES + s].rgb));
        exact.diff[t] = d;
    } else if (t < TP_PROBES + TP_SAMPLES) {
        int k = t - TP_PROBES;
        vec3 h = hash_pcg3(vec3(k, 5, 9));
        vec3 g = h * float(TP_N - 1);
        if (k % 8 == 0) g.x = floor(g.x);                 // on a cell face
        if (k % 16 == 0) g.y = floor(g.y);                // on an edge
        if (k % 32 == 0) g.z = floor(g.z);                // on a probe
        vec3 x = -TP_EXTENT + g * (2.0 * TP_EXTENT / float(TP_N - 1));
        tetrahedral_locate(x, tet, w);
        samples.w[2 * k] = w;
        samples.w[2 * k + 1] = vec4(w.x + w.y + w.z + w.w - 1.0, float(tet), 0.0, 0.0);
    }
}
