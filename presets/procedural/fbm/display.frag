#version 450
// Display: maps the normalised fBm value v = f/s in [0,1] to a colour. The field image is
// rgba16f so tests read the exact values; this pass only makes them visible.
#include "common/color.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D field;

void main() {
    float v = texture(field, uv).r;
    vec3 c;
    if (params.palette == PALETTE_GRAY) {
        c = vec3(v);
    } else if (params.palette == PALETTE_CLOUDS) {
        // Sky blue below the threshold, white clouds above (smoothstep as in cloudMap, 002 L2408).
        float cloud = smoothstep(0.45, 0.75, v);
        c = mix(vec3(0.18, 0.38, 0.75), vec3(1.0), cloud);
    } else {
        c = vec3(1.6, 1.0, 0.5) * v * v + vec3(0.3, 0.0, 0.0) * v;
    }
    // The target is rgba8_srgb: we write linear values, the hardware encodes sRGB on store.
    color = vec4(srgb_to_linear(clamp(c, 0.0, 1.0)), 1.0);
}
