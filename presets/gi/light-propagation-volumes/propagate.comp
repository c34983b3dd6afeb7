#version 450
// One propagation step (002_644d46bdce7e5305.txt L2567-2570: "6 propagation directions"): every
// cell sends its whole flux through its 6 faces (lpv_face_flux: shares that sum to exactly c0),
// and a cell receives, from the neighbour behind each face, the share that neighbour sent its way,
// re-emitted as a lobe along the direction of travel. At the volume's boundary a share that would
// leave is reflected back into its own cell as a lobe pointing inwards (closed: every side; open:
// all but the front, z = +1, where it leaves the box). So in a closed volume the total flux is
// conserved exactly, iteration after iteration (the test). Reads row pl_iteration, writes the next.
// (No geometry volume: the blocks do not block propagation; light leaks through them.)
layout(local_size_x = 64) in;

#include "gi/lpv_grid.glsl"

layout(std430) buffer Lpv { vec4 rec[]; } lpv;

void load(int row, ivec3 c, out vec3 c0, out vec3 cx, out vec3 cy, out vec3 cz) {
    int i = (row * LPV_CELLS + lpv_index(c)) * 4;
    c0 = lpv.rec[i].rgb;
    cx = lpv.rec[i + 1].rgb;
    cy = lpv.rec[i + 2].rgb;
    cz = lpv.rec[i + 3].rgb;
}

bool reflects(int k) { return params.closed || LPV_DIRS[k] != ivec3(0, 0, 1); }

void main() {
    int cell = int(gl_GlobalInvocationID.x);
    if (cell >= LPV_CELLS) return;
    ivec3 c = ivec3(cell % LPV_N, (cell / LPV_N) % LPV_N, cell / (LPV_N * LPV_N));
    int row = pl_iteration;
    vec3 n0 = vec3(0.0), nx = vec3(0.0), ny = vec3(0.0), nz = vec3(0.0);
    vec3 c0, cx, cy, cz, f[6];
    // received from the 6 neighbours
    for (int k = 0; k < 6; ++k) {
        ivec3 from = c - LPV_DIRS[k];  // travelling along +d_k into c
        if (any(lessThan(from, ivec3(0))) || any(greaterThanEqual(from, ivec3(LPV_N)))) continue;
        load(row, from, c0, cx, cy, cz);
        lpv_face_flux(c0, cx, cy, cz, f);
        vec3 d = vec3(LPV_DIRS[k]);
        n0 += f[k];
        nx += f[k] * LPV_LOBE * d.x;
        ny += f[k] * LPV_LOBE * d.y;
        nz += f[k] * LPV_LOBE * d.z;
    }
    // own shares that hit the boundary, reflected
    load(row, c, c0, cx, cy, cz);
    lpv_face_flux(c0, cx, cy, cz, f);
    for (int k = 0; k < 6; ++k) {
        ivec3 to = c + LPV_DIRS[k];
        if (all(greaterThanEqual(to, ivec3(0))) && all(lessThan(to, ivec3(LPV_N))) || !reflects(k)) continue;
        vec3 d = -vec3(LPV_DIRS[k]);
        n0 += f[k];
        nx += f[k] * LPV_LOBE * d.x;
        ny += f[k] * LPV_LOBE * d.y;
        nz += f[k] * LPV_LOBE * d.z;
    }
    int o = ((row + 1) * LPV_CELLS + cell) * 4;
    lpv.rec[o] = vec4(n0, 0.0);
    lpv.rec[o + 1] = vec4(nx, 0.0);
    lpv.rec[o + 2] = vec4(ny, 0.0);
    lpv.rec[o + 3] = vec4(nz, 0.0);
}
