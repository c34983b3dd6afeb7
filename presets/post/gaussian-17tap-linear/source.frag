#version 450
// Sharp features to blur: one-pixel dots and thin strokes, or a constant 1 for the energy test.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 src;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (params.pattern == PATTERN_CONSTANT) {
        src = vec4(1.0);
    } else if (params.pattern == PATTERN_DOTS) {
        bool dot = p.x % 12 == 6 && p.y % 12 == 6;
        bool cross_ = (p.x % 48 == 30 && p.y % 48 < 20) || (p.y % 48 == 40 && p.x % 48 < 20);
        src = vec4(dot ? 1.0 : 0.0, cross_ ? 1.0 : 0.0, dot || cross_ ? 1.0 : 0.0, 1.0);
    } else {
        // Block "text": rows of short bars of varying length, like lines of type.
        bool row = p.y % 14 < 3;
        bool word = fract(sin(float(p.x / 9 + 31 * (p.y / 14))) * 43758.5) < 0.7 && p.x % 9 < 7;
        src = vec4(vec3(row && word ? 1.0 : 0.0), 1.0);
    }
}
