#version 450
// The bake (000_c9f7e5de708ecbb3.txt L2157-2162, L2192-2196; 003_cfc3b5b225ddab3d.txt
// L383-401): "map back to worldspace to calculate lighting" — each light-map texel centre
// (i + 0.5) / N is taken back to its floor point and the view-independent diffuse irradiance
// is stored there. Only low resolution is needed: diffuse light varies slowly (shadow edges
// excepted). bake = true: this runs once, and again only when a param changes.
// With PREMULTIPLIED the albedo is multiplied in, at the light map's resolution: the
// "premultiply textures by light maps" of L2198-2199, and why it is bad (L2203-2214).
#include "lighting.glsl"
layout(location = 0) out vec4 lightmap;
#ifdef PREMULTIPLIED
uniform sampler2D albedo;
#endif
void main() {
    vec2 uv = gl_FragCoord.xy / vec2(params.lm_res);     // texel centre
    vec3 e = irradiance(floor_position(uv), vec3(0.0, 1.0, 0.0), true);
#ifdef PREMULTIPLIED
    e *= texture(albedo, uv * params.tiles).rgb;          // filtered to this resolution
#endif
    lightmap = vec4(e, 1.0);
}
