#version 450
// "Pass 2: read + collect all visible ids" (000_c9f7e5de708ecbb3.txt L6279): one thread per
// pixel of the id image marks the box it shows. The marked set is the exact visible set at this
// resolution: a box is marked iff it won the depth test at some pixel centre, so drawing only the
// marked boxes changes no pixel (conservative, PVS >= EVS, L6163-6168, here with equality).
layout(local_size_x = 8, local_size_y = 8) in;
#include "visibility/scene.glsl"
uniform usampler2D ids;
layout(std430) buffer Marked { uint flag[]; } marked;   // flag[i] = 1: object i is visible
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(ids, 0)))) return;
    uint id = texelFetch(ids, p, 0).r;
    // 0 = background, PL_VIS_OBJECTS + 1 = the wall: neither is a cullable object.
    if (id != 0u && id <= uint(PL_VIS_OBJECTS)) marked.flag[id - 1u] = 1u;   // any thread may: same value
}
