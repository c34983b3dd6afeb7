#version 450
// dst = src, texel for texel (the grid's current state <- first bounce, or <- the bounce just
// computed). A compute copy: it works for any 3D storage format without a blit.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(rgba32f) readonly uniform image3D src;
layout(rgba32f) writeonly uniform image3D dst;
#include "gi/rh_grid.glsl"
void main() {
    // The grid is cached once the injection stops (gi/rh_inject.comp), and while it converges the
    // exchange runs on every rh_update-th frame: in both cases `dst` keeps what it holds.
    if (!rh_exchange_runs()) return;
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, imageSize(dst)))) return;
    imageStore(dst, p, imageLoad(src, p));
}
