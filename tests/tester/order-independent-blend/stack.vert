#version 450
// Four overlapping quads with different colours and alpha 0.5, all covering the centre.
layout(location = 0) in vec3 position;
layout(location = 0) flat out vec4 v_color;
void main() {
    int i = gl_InstanceIndex;
    gl_Position = vec4(position.xz * 1.5 + vec2(i % 2, i / 2) * 0.2 - 0.1, 0.5, 1.0);
    const vec3 c[4] = vec3[](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 1, 0));
    v_color = vec4(c[i] * 0.25, 0.5);
}
