#version 450
// The bright pass of 002_644d46bdce7e5305.txt L854-869 (lens flare; described at L813) and L698-704 (bloom):
// average each 4x4 block (one quarter-resolution texel), keep what exceeds the threshold
// (1.0 in HDR: the 0..1 range stays unbloomed), doubled:
//   bright = max(0, mean_4x4(c) - params.threshold) * 2
// Reads `hdr`, writes `bright` (bind to rename); the preset declares params.threshold.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 bright;
uniform sampler2D hdr;
void main() {
    ivec2 base = ivec2(gl_FragCoord.xy) * 4, last = ivec2(frame.resolution.xy) - 1;
    vec3 c = vec3(0.0);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) c += texelFetch(hdr, min(base + ivec2(x, y), last), 0).rgb;
    vec3 m = c / 16.0;
    bright = vec4(mix(vec3(0.0), m, greaterThan(m, vec3(params.threshold))) * 2.0, 1.0);  // keep the bright blocks
}
