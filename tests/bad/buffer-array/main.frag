#version 450
layout(location = 0) out vec4 color;
layout(std430) readonly buffer Items {
    float v[];
} items[2];
void main() { color = vec4(items[0].v[0] + items[1].v[0]); }
