#version 450
// A positive pseudo-random value per pixel (r), and a mask (a) on every third pixel.
layout(location = 0) out vec4 values;
layout(location = 1) out vec4 mask;
void main() {
    vec2 p = floor(gl_FragCoord.xy);
    // +0.5: no pixel gets fract(0) = 0, so the min is not pinned at 1 for every subset
    float v = 1.0 + 10.0 * fract(sin(dot(p + 0.5, vec2(12.9898, 78.233))) * 43758.5453);
    values = vec4(v, 0.0, 0.0, 1.0);
    mask = vec4(0.0, 0.0, 0.0, mod(p.x + p.y * 37.0, 3.0) == 0.0 ? 1.0 : 0.0);
}
