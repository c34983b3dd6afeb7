#version 450
// Row 0 of the volume: the injected fixed-point sums as floats.
layout(local_size_x = 64) in;

#include "gi/lpv_grid.glsl"

layout(std430) readonly buffer Inject { int v[]; } inject;
layout(std430) writeonly buffer Lpv { vec4 rec[]; } lpv;

void main() {
    int cell = int(gl_GlobalInvocationID.x);
    if (cell >= LPV_CELLS) return;
    for (int s = 0; s < 4; ++s) {
        int i = (cell * 4 + s) * 3;
        lpv.rec[cell * 4 + s] = vec4(vec3(inject.v[i], inject.v[i + 1], inject.v[i + 2]) / 16777216.0, 0.0);
    }
}
