#version 450
// Test-only audit of the marked set against the id image, pixel by pixel: `missing` counts the
// pixels whose box was not marked (must be 0: every id in the buffer is in the set), and
// pixels[i] the pixels box i shows (a box is marked iff pixels[i] > 0: the set has no extra).
layout(local_size_x = 8, local_size_y = 8) in;
#include "visibility/scene.glsl"
uniform usampler2D ids;
layout(std430) readonly buffer Marked { uint flag[]; } marked;
layout(std430) buffer Audit { uint missing; uint pixels[]; } audit;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(ids, 0)))) return;
    uint id = texelFetch(ids, p, 0).r;
    if (id == 0u || id > uint(PL_VIS_OBJECTS)) return;
    atomicAdd(audit.pixels[id - 1u], 1u);
    if (marked.flag[id - 1u] == 0u) atomicAdd(audit.missing, 1u);
}
