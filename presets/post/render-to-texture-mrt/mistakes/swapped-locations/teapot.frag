#version 450
// One fragment shader, several outputs (000_c9f7e5de708ecbb3.txt L2026-2039): location 0 the
// lit colour, location 1 the normal, location 2 the colour again (for the test).
layout(location = 0) in vec3 v_normal;
layout(location = 0) out vec4 color0;
layout(location = 1) out vec4 color1;
layout(location = 2) out vec4 color2;
void main() {
    vec3 n = normalize(v_normal);
    vec3 c = params.tint * (0.2 + 0.8 * max(dot(n, normalize(vec3(0.5, 0.8, 0.6))), 0.0));
    color0 = vec4(n * 0.5 + 0.5, 1.0);   // colour first, normal second...
    color1 = vec4(c, 1.0);
    color2 = color0;
}
