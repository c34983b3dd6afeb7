#version 450
// Source image with sharp features so the blur is easy to see and to test.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main() {
    vec2 p = gl_FragCoord.xy;
    if (params.pattern == PATTERN_DOTS) {
        // A lattice of one-pixel dots and a few bright squares.
        bool dot = (int(p.x) % 16 == 8) && (int(p.y) % 16 == 8);
        bool square = (int(p.x) / 32 + int(p.y) / 32) % 5 == 0 && (int(p.x) % 32) < 6 && (int(p.y) % 32) < 6;
        color = vec4(dot ? 1.0 : 0.0, square ? 1.0 : 0.0, uv.x, 1.0);
    } else if (params.pattern == PATTERN_STRIPES) {
        color = vec4(vec3(step(0.5, fract(p.x / 8.0))), 1.0);
    } else {
        color = vec4(0.5);
    }
}
