#version 450
// The photon map's search structure, a counting sort of the stored photons into the uniform grid
// of gi/photon_map.glsl (in place of the kd-tree the course names, L5094: on a GPU a grid is
// built with three data-parallel steps and searched without a stack).
//   STEP 0: count[c] += 1 for every stored photon in cell c         (atomicAdd)
//   STEP 1: start = exclusive prefix sum of count, cursor = start     (one thread: 32768 cells)
//   STEP 2: sorted[atomicAdd(cursor[c], 1)] = record                  (order inside a cell is
//           arbitrary; the gather only sums, so the picture does not depend on it)
layout(local_size_x = 64) in;

#include "gi/photon_map.glsl"

layout(std430) readonly buffer Photons { vec4 rec[]; } photons;
layout(std430) buffer Count { uint count[]; } counts;
layout(std430) buffer Start { uint start[]; } starts;
layout(std430) buffer Cursor { uint cursor[]; } cursors;
layout(std430) buffer Sorted { uint record[]; } sorted;

bool stored(int r) { return photons.rec[3 * r].x < 1e8; }
int cell_of(int r) { return photon_cell_index(photon_cell_coords(photons.rec[3 * r].xyz)); }

void main() {
    int r = int(gl_GlobalInvocationID.x);
#if STEP == 0
    if (r < PM_RECORDS && stored(r)) atomicAdd(counts.count[cell_of(r)], 1u);
#elif STEP == 1
    if (r != 0) return;
    uint sum = 0u;
    for (int c = 0; c < PM_CELLS; ++c) {
        starts.start[c] = sum;
        cursors.cursor[c] = sum;
        sum += counts.count[c];
    }
    starts.start[PM_CELLS] = sum;
#else
    if (r < PM_RECORDS && stored(r)) sorted.record[atomicAdd(cursors.cursor[cell_of(r)], 1u)] = uint(r);
#endif
}
