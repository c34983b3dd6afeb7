#version 450
// A black/white checker written to two 8-bit targets: a UNORM one (what is written is stored)
// and an sRGB one (linear values encoded on store: 0 and 1 encode to the same bytes 0 and 255).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 checker_unorm;
layout(location = 1) out vec4 checker_srgb;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) / params.cells;
    float v = float((p.x + p.y) & 1);
    checker_unorm = vec4(vec3(v), 1.0);
    checker_srgb = vec4(vec3(v), 1.0);
}
