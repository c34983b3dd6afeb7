#version 450
layout(location = 0) out float counts;
layout(std430) readonly buffer fragments { uint shaded; };
void main() { counts = float(shaded); }
