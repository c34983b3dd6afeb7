#version 450
layout(location = 0) out vec4 color;
layout(std140) uniform table { vec4 rows[64]; };
layout(std430) readonly buffer items { float values[]; };
void main() { color = rows[0] + vec4(values[0]); }
