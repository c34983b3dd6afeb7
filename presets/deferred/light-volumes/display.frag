#version 450
// The lit image, or the number of lights that shaded each pixel (0 black, 1 blue ... 8+ red).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D lit;
uniform usampler2D count;
void main() {
    if (params.show == SHOW_COUNT) {
        float k = float(texelFetch(count, ivec2(gl_FragCoord.xy), 0).r);
        ldr = vec4(k == 0.0 ? vec3(0.0) : mix(vec3(0.1, 0.2, 0.8), vec3(1.0, 0.15, 0.05), clamp((k - 1.0) / 7.0, 0.0, 1.0)), 1.0);
    } else {
        ldr = vec4(clamp(texelFetch(lit, ivec2(gl_FragCoord.xy), 0).rgb, 0.0, 1.0), 1.0);  // one texel, not a filtered sample
    }
}
