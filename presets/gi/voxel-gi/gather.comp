#version 450
// The indirect bounce gathered in voxel space: from every marked cell, the same 6 cones shade.frag
// traces per pixel with `per_pixel` (one along the surface normal, five at 60 degrees, weights
// 0.25 / 0.15), stored as (incoming radiance, 1) so the shading can interpolate it between
// surface cells (empty cells are (0, 0) and drop out when dividing by the weight). Per pixel the
// cones cost ~570 ms a frame on lavapipe at 640x360; per cell (~16k marked) a few ms once.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#define VX_CONES 1
#include "gi/voxel_scene.glsl"
#include "gi/voxel_cone.glsl"

layout(rgba16f) writeonly uniform image3D indirect_out;

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, ivec3(VX_N)))) return;
    uint id = imageLoad(voxels, c).r;
    if (id == 0u) {
        imageStore(indirect_out, c, vec4(0.0));
        return;
    }
    vec3 n = voxel_face_normal(int(id - 1u) % 8);
    vec3 x = voxel_lo(c) + 0.5 * VX_SIZE;
    imageStore(indirect_out, c, vec4(voxel_hemisphere(x + n * 1.5 * VX_SIZE, n), 1.0));
}
