#version 450
layout(location = 0) out vec4 color;
layout(std430) readonly buffer Acc { float total; } acc;
void main() { color = vec4(acc.total); }
