#version 450
#extension GL_EXT_shader_atomic_float : require
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430) buffer Acc { float total; } acc;
void main() { atomicAdd(acc.total, 0.5); }
