#version 450
// The light that passed through each cell: the sum of rows 0 .. iterations (LPV accumulates the
// propagation steps), written to three 3D images (one per colour channel: c0, c1.x, c1.y, c1.z)
// that the shading samples trilinearly.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "gi/lpv_grid.glsl"

layout(std430) readonly buffer Lpv { vec4 rec[]; } lpv;
layout(rgba16f) writeonly uniform image3D sh_r;
layout(rgba16f) writeonly uniform image3D sh_g;
layout(rgba16f) writeonly uniform image3D sh_b;

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, ivec3(LPV_N)))) return;
    vec3 s[4] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    for (int row = 0; row <= params.iterations; ++row)
        for (int k = 0; k < 4; ++k) s[k] += lpv.rec[(row * LPV_CELLS + lpv_index(c)) * 4 + k].rgb;
    imageStore(sh_r, c, vec4(s[0].r, s[1].r, s[2].r, s[3].r));
    imageStore(sh_g, c, vec4(s[0].g, s[1].g, s[2].g, s[3].g));
    imageStore(sh_b, c, vec4(s[0].b, s[1].b, s[2].b, s[3].b));
}
