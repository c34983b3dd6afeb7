#version 450
// A member with a repeat of its own runs all its iterations in every group iteration:
// z.r += 1 + 10 * group iteration + 1000 * own iteration; z.g += its own count.
layout(local_size_x = 4, local_size_y = 4) in;
layout(rg32f) uniform image2D z;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    vec4 v = imageLoad(z, p);
    v.r += 1.0 + 10.0 * float(pl_group_iteration) + 1000.0 * float(pl_iteration);
    v.g += float(pl_iteration_count);
    imageStore(z, p, v);
}
