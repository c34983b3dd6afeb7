#version 450
// Add the (bilinearly upsampled) bloom to the original, then tone map (000 L3092: "add filtered
// image to original image"; 002 L714).
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
layout(location = 1) out vec4 added;
uniform sampler2D hdr;
uniform sampler2D bloom;
void main() {
    vec3 add = params.strength * texture(bloom, uv).rgb;
    if (params.split && uv.x < 0.5) add = vec3(0.0);
    vec3 base = texture(hdr, uv).rgb;
    vec3 c = base;
    result = vec4(tonemap_hejl(c * params.exposure) + add, 1.0);  // the glow on top of the picture
    if (params.split && abs(uv.x - 0.5) < 0.0015) result = vec4(1.0, 0.8, 0.2, 1.0);
    added = vec4(c - base, 1.0);  // what the composite really added (bloom-only-adds)
}
