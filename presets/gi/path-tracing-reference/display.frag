#version 450
// The accumulated radiance to the screen: exposure, then the sRGB target encodes. A pixel the
// interleaved trace has not reached yet since the last reset (alpha 0) is interpolated
// bilinearly between the first pixels of its tile and the three next tiles, which were traced
// on the first frame (interleave.glsl): a moved camera shows a blurred picture at once, never
// black holes or k x k blocks.
#include "interleave.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D radiance;

vec3 tile_corner(ivec2 q) { return texelFetch(radiance, min(q, textureSize(radiance, 0) - 1), 0).rgb; }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 r = texelFetch(radiance, p, 0);
    if (r.a == 0.0) {
        int k = pt_interleave();
        ivec2 t = p - p % k;
        vec2 f = vec2(p % k) / float(k);
        vec3 bottom = mix(tile_corner(t), tile_corner(t + ivec2(k, 0)), f.x);
        vec3 top = mix(tile_corner(t + ivec2(0, k)), tile_corner(t + ivec2(k, k)), f.x);
        r.rgb = mix(bottom, top, f.y);
    }
    color = vec4(r.rgb * params.exposure, 1.0);
}
