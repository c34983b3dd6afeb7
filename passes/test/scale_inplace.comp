#version 450
// Test helper: halves a storage image in place (read-modify-write of the same texel).
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f) uniform image2D img;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(img)))) return;
    imageStore(img, p, imageLoad(img, p) * 0.5);
}
