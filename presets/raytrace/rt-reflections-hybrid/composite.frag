#version 450
// c = mix(lit, reflection, map) (000 L3990-3993) with the reflection from, in order
// (000 L5797-5799): SSR where it hit, the traced ray where SSR left a gap, the environment
// where the ray escaped too (or nothing, fallback off). Where SSR hit, this is envmap/ssr's
// composite exactly; so it is where neither SSR nor the ray found anything.
// show: the composite, the reflection alone, SSR hits (as envmap/ssr), or the source of every
// mirror pixel (green SSR, blue ray, red environment).
#include "mirror/scene.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D lit;
uniform sampler2D gbuf;
uniform sampler2D depth;
uniform sampler2D ssr;
uniform sampler2D rays;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 base = texelFetch(lit, p, 0).rgb;
    // ssr_resolution = half: SSR and the rays once per 2x2 block, the nearest.
    ivec2 ph = params.ssr_resolution == SSR_RESOLUTION_HALF ? p / 2 : p;
    vec4 g = texelFetch(gbuf, p, 0);
    hdr = vec4(base, 1.0);
    if (g.w <= 0.0) {
        if (params.show != SHOW_FINAL) hdr = vec4(base * 0.25, 1.0);
        return;
    }
    vec4 s = texelFetch(ssr, ph, 0), r = texelFetch(rays, ph, 0);  // read on the mirror only
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, texelFetch(depth, p, 0).r, 1.0);
    vec3 V = normalize(w.xyz / w.w - frame.camera_pos.xyz), R = reflect(V, normalize(g.xyz));
    vec3 refl = s.a > 0.0 ? s.rgb : r.a > 0.0 ? r.rgb : params.fallback ? sky_color(R) : base;
    hdr = vec4(mix(base, refl, g.w), 1.0);
    if (params.show == SHOW_REFLECTION) hdr = vec4(refl, 1.0);
    if (params.show == SHOW_HITS) hdr = vec4(s.a > 0.0 ? vec3(0.1, 0.8, 0.2) : vec3(0.8, 0.1, 0.1), 1.0);
    if (params.show == SHOW_SOURCES) hdr = vec4(s.a > 0.0 ? vec3(0.1, 0.8, 0.2) : r.a > 0.0 ? vec3(0.15, 0.3, 0.9) : vec3(0.8, 0.1, 0.1), 1.0);
}
