#version 450
layout(location = 0) out vec4 out_a;
layout(location = 1) out vec4 out_b;
layout(location = 2) out float out_c;
void main() {
    out_a = vec4(0.25, 0.5, 0.75, 1.0);
    out_b = vec4(1.5, -2.0, 3.0, gl_FragCoord.x);
    out_c = 10.0 * gl_FragCoord.y;
}
