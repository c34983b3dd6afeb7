#version 450
layout(local_size_x = 64) in;
layout(std430) buffer Out { float v[]; } result;
shared float big[100000000];
void main() {
    big[gl_LocalInvocationIndex] = 1.0;
    barrier();
    result.v[gl_LocalInvocationIndex] = big[63 - gl_LocalInvocationIndex];
}
