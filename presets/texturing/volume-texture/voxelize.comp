#version 450
// Bake: sample the phantom at every voxel centre into the 3D image (a storage image here,
// a sampled 3D texture afterwards). 64^3 texels of rgba16f = 2 MiB; the same at 512^3 would be
// 1 GiB — "lots of memory needed" (L1768).
#include "phantom.glsl"
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(rgba16f) uniform writeonly image3D volume;
void main() {
    ivec3 ijk = ivec3(gl_GlobalInvocationID);
    int n = imageSize(volume).x;
    if (any(greaterThanEqual(ijk, imageSize(volume)))) return;
    imageStore(volume, ijk, vec4(phantom(voxel_centre(ijk, n)), 0.0, 0.0, 1.0));
}
