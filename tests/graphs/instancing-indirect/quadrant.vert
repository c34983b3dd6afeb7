#version 450
// The plane mesh lies in XZ with size 1 (x, z in [-0.5, 0.5]); instance i scales it to a
// quadrant of the screen.
layout(location = 0) in vec3 position;
layout(location = 0) flat out vec4 v_color;
void main() {
    int i = gl_InstanceIndex;
    vec2 centre = vec2((i % 2) == 0 ? -0.5 : 0.5, (i / 2) == 0 ? -0.5 : 0.5);
    gl_Position = vec4(centre + position.xz, 0.5, 1.0);
    v_color = vec4(float(i + 1) / 4.0);
}
