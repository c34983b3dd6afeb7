#version 450
layout(local_size_x = 64) in;
layout(std430) buffer Out { float v[]; } result;
// 60,000 bytes: within what some devices offer, above lavapipe's 32 KiB.
shared float big[15000];
void main() {
    big[gl_LocalInvocationIndex] = 1.0;
    barrier();
    result.v[gl_LocalInvocationIndex] = big[63 - gl_LocalInvocationIndex];
}
