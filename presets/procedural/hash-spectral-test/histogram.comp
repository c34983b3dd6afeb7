#version 450
// The spectral test as counts (004_9a40ad89bdfc582a.txt L616-680): params.count consecutive
// points (see sequences.glsl) binned into a 32 x 32 grid with atomics. Each invocation takes
// kRun consecutive indices (one jump-ahead, then kRun + 2 steps), counts into a workgroup-shared
// histogram, and adds the non-zero cells to the global one (fewer global atomics).
#include "sequences.glsl"
layout(local_size_x = 64) in;
layout(std430) buffer Histogram { uint cells[1024]; } histogram;  // cell = row * 32 + column
shared uint local_cells[1024];

const uint kRun = 64u;       // consecutive points per invocation (threads = count / kRun)
const uint kCellShift = 27u; // the top 5 bits of a 32-bit fraction: 32 cells per axis

void main() {
    for (uint c = gl_LocalInvocationIndex; c < 1024u; c += gl_WorkGroupSize.x) local_cells[c] = 0u;
    barrier();
    uint count = uint(params.count);
    uint first = gl_GlobalInvocationID.x * kRun;
    if (first < count) {
        Sequence s = sequence_at(first);
        uint u0 = sequence_next(s), u1 = sequence_next(s);
        for (uint i = first; i < min(first + kRun, count); ++i) {
            uint u2 = sequence_next(s);
            uvec2 cell = plotted_point(u0, u1, u2) >> kCellShift;
            atomicAdd(local_cells[cell.y * 32u + cell.x], 1u);
            u0 = u1;
            u1 = u2;
        }
    }
    barrier();
    for (uint c = gl_LocalInvocationIndex; c < 1024u; c += gl_WorkGroupSize.x)
        if (local_cells[c] != 0u) atomicAdd(histogram.cells[c], local_cells[c]);
}
