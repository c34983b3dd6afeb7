#version 450
// The image, or the overdraw: fragments shaded per pixel as a heat ramp (1 blue ... 8+ red).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D color;
uniform usampler2D overdraw;
void main() {
    if (params.show == SHOW_OVERDRAW) {
        float k = float(texelFetch(overdraw, ivec2(gl_FragCoord.xy), 0).r);
        ldr = vec4(k == 0.0 ? vec3(0.0) : mix(vec3(0.1, 0.2, 0.8), vec3(1.0, 0.15, 0.05), clamp((k - 1.0) / 7.0, 0.0, 1.0)), 1.0);
    } else {
        ldr = vec4(texture(color, uv).rgb, 1.0);
    }
}
