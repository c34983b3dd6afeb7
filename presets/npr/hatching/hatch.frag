#version 450
// Hatching from the G-buffer (000 L3229-3240): the tone from the normal — ambient plus Lambert,
// t = ambient + (1 - ambient) max(n.l, 0) — and ink wherever the stroke texture, read at the
// surface coordinates (u, v), holds a stroke that the darkness 1 - t calls for: the tile's
// coverage C up to that stroke is <= 1 - t (coverage.frag). The strokes therefore follow the
// surface, and their number grows as the surface turns from the light.
#include "light.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out float ink;   // 1 = ink, 0 = paper (tests)
uniform sampler2D normal;
uniform sampler2D surface_uv;
uniform sampler2D stroke_index;
uniform sampler2D stroke_coverage;

float tone_at(vec3 n) {
    vec3 l = light_direction();
    return params.ambient + (1.0 - params.ambient) * max(dot(n, l), 0.0);
}

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 nw = texelFetch(normal, px, 0);
    ink = 0.0;
    if (nw.w == 0.0) {
        color = vec4(params.paper, 1.0);
        return;
    }
    float tone = tone_at(normalize(nw.xyz));
    float index = texture(stroke_index, texelFetch(surface_uv, px, 0).xy).r;
    float rank = texelFetch(stroke_coverage, ivec2(int(index), 0), 0).r;  // C(index)
    ink = rank <= 1.0 - tone ? 1.0 : 0.0;
    // Outlines (000 L3225: "NPR often emphasizes object edges, silhouettes"): a neighbour that
    // is background or whose normal turns by more than kCrease marks an edge.
    if (params.outline) {
        const float kCrease = 0.6;  // 1 - cos(66 degrees)
        for (int k = 0; k < 4; ++k) {
            ivec2 q = clamp(px + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0), ivec2(0), ivec2(frame.resolution.xy) - 1);
            vec4 m = texelFetch(normal, q, 0);
            if (m.w == 0.0 || 1.0 - dot(normalize(m.xyz), normalize(nw.xyz)) > kCrease) ink = 1.0;
        }
    }
    vec3 c = mix(params.paper, params.ink, ink);
    if (params.show == SHOW_TONE) c = vec3(tone);
    if (params.show == SHOW_STROKES) c = vec3(rank);
    color = vec4(c, 1.0);
}
