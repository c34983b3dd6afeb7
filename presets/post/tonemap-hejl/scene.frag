#version 450
// An HDR scene with a wide range: a sky (0.2..1), a sun (radiance 60), a lit wall with a dark
// doorway, and along the bottom a ramp whose value doubles every 1/8 of the width (2^-4 .. 2^4),
// so each operator's shoulder and toe are visible. Or a constant, for the curve tests.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
void main() {
    if (params.source == SOURCE_CONSTANT) {
        hdr = vec4(vec3(params.value), 1.0);
        return;
    }
    vec3 c = mix(vec3(1.0, 0.95, 0.9), vec3(0.2, 0.35, 0.7), uv.y / 0.6);       // sky
    if (length((uv - vec2(0.75, 0.18)) * vec2(frame.aspect, 1.0)) < 0.05) c = vec3(60.0, 55.0, 45.0);  // sun
    if (uv.y > 0.45) c = vec3(2.2, 1.8, 1.4) * (1.2 - uv.y);                      // sunlit wall
    if (uv.y > 0.5 && abs(uv.x - 0.3) < 0.08) c = vec3(0.02, 0.025, 0.03);        // doorway
    if (uv.y > 0.88) c = vec3(exp2(mix(-4.0, 4.0, floor(uv.x * 8.0) / 7.0)));     // ramp 1/16 .. 16
    hdr = vec4(c, 1.0);
}
