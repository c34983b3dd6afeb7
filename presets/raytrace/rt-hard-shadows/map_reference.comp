#version 450
// rt-hard-shadows' test-only reference: the same G-buffer pixels shadowed by a 4096^2 shadow map
// (presets/shadows/shadow-map's method: one nearest compare after moving the point towards the
// light by texel (c + s tan theta), passes/shadows/shadow_map.glsl) and the same N.L rule, into
// `ref`: r = visibility. At 4096^2 a map texel is 8.5 / 4096 = 0.002 world units, so its shadow
// edges lie within a pixel of the ray-traced ones.
layout(local_size_x = 8, local_size_y = 8) in;
#include "shadows/shadow_map.glsl"
#include "shadows/light.glsl"
uniform sampler2D gpos;
uniform sampler2D gnrm;
uniform sampler2D shadow;
layout(rgba16f) writeonly uniform image2D ref;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(ref)))) return;
    vec4 g = texelFetch(gpos, px, 0);
    if (g.w < 0.5) {
        imageStore(ref, px, vec4(1.0, 0.0, 0.0, 0.0));
        return;
    }
    vec3 p = g.xyz, n = texelFetch(gnrm, px, 0).xyz, l = shadow_light_dir(p);
    float v = 0.0;
    if (dot(n, l) > 0.0) {
        float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
        float b = shadow_bias_world(texel, dot(n, l), 1.0, 2.0);
        v = shadow_nearest(shadow, shadow_project(cameras.light.view_proj, p + b * l));
    }
    imageStore(ref, px, vec4(v, 0.0, 0.0, 1.0));
}
