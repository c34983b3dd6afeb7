#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f) uniform image2D cov;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(cov)))) return;  // the last groups overhang
    imageStore(cov, p, imageLoad(cov, p) + 1.0);
}
