#version 450
layout(location = 0) in vec3 v_color;
layout(location = 0) out vec4 color;
layout(location = 1) out float sum;
void main() {
    color = vec4(v_color, 1.0);
    sum = v_color.r + v_color.g + v_color.b;  // barycentric weights sum to 1
}
