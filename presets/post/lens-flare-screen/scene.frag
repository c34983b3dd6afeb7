#version 450
// The input: a dim sky (below the flare threshold) and one bright square light, in linear HDR.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
void main() {
    vec2 d = abs(gl_FragCoord.xy - params.light * frame.resolution.xy);
    bool in_light = max(d.x, d.y) < params.radius;
    hdr = vec4(in_light ? vec3(params.intensity) : vec3(params.background), 1.0);
}
