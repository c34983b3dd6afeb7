#version 450
// The gather at 1/RSM_DIV of the view's resolution in each axis (the RSM paper's screen-space
// interpolation: indirect light is smooth, so it is computed sparsely and interpolated where the
// geometry agrees, rsm_compose.frag). Each low-res texel gathers gi_irradiance (the preset's
// gather.glsl: the RSM's texels or the VPLs) at the G-buffer point at the centre of its block and
// keeps that point's position and normal for the upsampling's weights.
layout(local_size_x = 8, local_size_y = 8) in;
#include "gather.glsl"
uniform sampler2D g_normal, g_pos;
layout(rgba32f) uniform writeonly image2D ind, ind_n, ind_p;
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, imageSize(ind)))) return;
    ivec2 px = min(q * RSM_DIV + RSM_DIV / 2, ivec2(frame.resolution.xy) - 1);
    vec4 pos = texelFetch(g_pos, px, 0);
    vec3 n = texelFetch(g_normal, px, 0).xyz;
    vec3 e = pos.w > 0.0 ? gi_irradiance(pos.xyz, n) : vec3(0.0);
    imageStore(ind, q, vec4(e, pos.w));
    imageStore(ind_n, q, vec4(n, 0.0));
    imageStore(ind_p, q, pos);
}
