#version 450
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/bvh.glsl"
layout(rgba8) uniform writeonly image2D ldr;
void main() {
    PlHit h = pl_no_hit(1e30);
    pl_bvh_closest(0u, mat4(1.0), 0, vec3(0, 0.5, 3), vec3(0, 0, -1), 0.0, h);
    imageStore(ldr, ivec2(gl_GlobalInvocationID.xy), vec4(h.instance >= 0 ? 1.0 : 0.0));
}
