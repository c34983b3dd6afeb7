#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba8) uniform writeonly image2D hdr;
void main() { imageStore(hdr, ivec2(gl_GlobalInvocationID.xy), vec4(1)); }
