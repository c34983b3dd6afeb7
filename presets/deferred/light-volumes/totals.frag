#version 450
layout(location = 0) out float totals;
layout(std430) readonly buffer shaded { uint samples; };
void main() { totals = float(samples); }
