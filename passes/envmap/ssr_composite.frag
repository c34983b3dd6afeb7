#version 450
// envmap/ssr's composite, shared with raytrace/rt-reflections-hybrid's test-only ssr_composite.
// c = mix(lit, reflection, map): the reflection map decides per pixel (000 L3990-3993). Where
// the ray missed, the environment in direction R stands in (000 L4124: "blend with
// cubemaps"), or nothing (fallback off). Where the map is 0 the lit image passes untouched.
// show: the composite, the reflection alone, or hits (green) / fallbacks (red) on the mirror.
#include "mirror/scene.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D lit;
uniform sampler2D gbuf;
uniform sampler2D depth;
uniform sampler2D ssr;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 base = texelFetch(lit, p, 0).rgb;
    // ssr_resolution = half: one ray per 2x2 block, the nearest (passes/envmap/ssr.frag).
    ivec2 ps = params.ssr_resolution == SSR_RESOLUTION_HALF ? p / 2 : p;
    vec4 g = texelFetch(gbuf, p, 0);
    hdr = vec4(base, 1.0);
    if (g.w <= 0.0) {
        if (params.show != SHOW_FINAL) hdr = vec4(base * 0.25, 1.0);
        return;
    }
    vec4 s = texelFetch(ssr, ps, 0);  // read on the mirror only
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, texelFetch(depth, p, 0).r, 1.0);
    vec3 V = normalize(w.xyz / w.w - frame.camera_pos.xyz), R = reflect(V, normalize(g.xyz));
    vec3 refl = s.a > 0.0 ? s.rgb : params.fallback ? sky_color(R) : base;
    hdr = vec4(mix(base, refl, g.w), 1.0);
    if (params.show == SHOW_REFLECTION) hdr = vec4(refl, 1.0);
    if (params.show == SHOW_HITS) hdr = vec4(s.a > 0.0 ? vec3(0.1, 0.8, 0.2) : vec3(0.8, 0.1, 0.1), 1.0);
}
