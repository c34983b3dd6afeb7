#version 450
// One level of the radiance mip chain: each cell the mean of its 8 children (premultiplied
// radiance and coverage).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

uniform sampler3D src;
layout(rgba16f) writeonly uniform image3D dst;

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, imageSize(dst)))) return;
    vec4 s = vec4(0.0);
    for (int k = 0; k < 8; ++k) s += texelFetch(src, 2 * c + ivec3(k & 1, (k >> 1) & 1, k >> 2), 0);
    imageStore(dst, c, s * 0.125);
}
