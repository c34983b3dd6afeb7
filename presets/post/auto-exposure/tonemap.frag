#version 450
// Exposure from the adapted mean: key / L_adapted (002 L650 with a fixed key), then Hejl. Bars
// at the bottom-left: this frame's mean (top) and the adapted one (bottom), on a log scale from
// 2^-8 (empty) to 2^4 (half the width).
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D hdr;
uniform sampler2D lum;
uniform sampler2D adapted;
void main() {
    float l_adapted = texelFetch(adapted, ivec2(0), 0).r;
    float exposure = params.key / max(l_adapted, 1e-4);
    vec3 c = tonemap_hejl(texture(hdr, uv).rgb * exposure);
    if (params.show_bar && uv.y > 0.9 && uv.x < 0.5) {
        float v = uv.y < 0.95 ? textureLod(lum, vec2(0.5), 16.0).r : l_adapted;
        c = uv.x < 0.5 * clamp((log2(max(v, 1e-6)) + 8.0) / 12.0, 0.0, 1.0) ? (uv.y < 0.95 ? vec3(1.0, 0.8, 0.2) : vec3(0.3, 0.8, 1.0)) : vec3(0.1);
    }
    result = vec4(c, 1.0);
}
