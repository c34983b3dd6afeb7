#version 450
// Texel (x, y) of the 8x8 image holds (x / 7, y / 7, 1 - x / 7): every texel differs from its
// neighbours in red or green, so the viewer's zoomed squares can be told apart in a capture.
layout(location = 0) out vec4 o;
void main() {
    vec2 t = floor(gl_FragCoord.xy) / 7.0;
    o = vec4(t.x, t.y, 1.0 - t.x, 1.0);
}
