#version 450
// y.r += x + 100 * g (g = the group's iteration, seen as pl_iteration by a member without a
// repeat of its own); y.g += the group's count.
layout(local_size_x = 4, local_size_y = 4) in;
uniform sampler2D x;                 // what `add` wrote in this group iteration
layout(rg32f) uniform image2D y;     // in place
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec4 v = imageLoad(y, p);
    v.r += texelFetch(x, p, 0).r + 100.0 * float(pl_iteration);
    v.g += float(pl_iteration_count);
    imageStore(y, p, v);
}
