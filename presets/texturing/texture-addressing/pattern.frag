#version 450
// A 4x4 asymmetric pattern: red grows with x, green with y, blue marks texel (0,0).
layout(location = 0) out vec4 color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = vec4((float(p.x) + 1.0) / 4.0, (float(p.y) + 1.0) / 4.0, p == ivec2(0) ? 1.0 : 0.0, 1.0);
}
