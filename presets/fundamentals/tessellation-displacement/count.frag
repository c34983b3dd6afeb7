#version 450
// The geometry shader's triangle counter as an image, so a test can probe it.
layout(location = 0) out float count;
layout(std430) readonly buffer tris { uint emitted; };
void main() { count = float(emitted); }
