#version 450
// L0 + L1 from their separately accumulated images (the Neumann series' first two terms,
// 000_c9f7e5de708ecbb3.txt L5014-5037), to compare with the bounces = 1 render.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) uniform writeonly image2D l0_plus_l1;
uniform sampler2D l0;
uniform sampler2D l1;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(l0_plus_l1)))) return;
    imageStore(l0_plus_l1, p, vec4(texelFetch(l0, p, 0).rgb + texelFetch(l1, p, 0).rgb, 1.0));
}
