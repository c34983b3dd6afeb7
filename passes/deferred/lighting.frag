#version 450
// Pass 2 of deferred shading (000 L2900-2905): a fullscreen pass reads the G-buffer and sums
// every light — shading cost O(pixels x lights) instead of O(fragments drawn x lights), so
// overdraw no longer multiplies the lighting. PACKED reads the 12-byte layout: octahedral
// normal, and the position rebuilt from the depth buffer through the inverse view-projection.
#include "deferred/lights.glsl"
#include "deferred/octahedral.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
uniform sampler2D albedo;
uniform sampler2D normal;
#ifdef PACKED
uniform sampler2D normal_oct;
uniform sampler2D depth;
#else
uniform sampler2D position;
#endif

const float kShininess = 32.0;
// ACTIVE (an expression) skips the work when nobody looks at the result.
#ifndef ACTIVE
#define ACTIVE true
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    if (!(ACTIVE) || texelFetch(normal, px, 0).w == 0.0) {  // inactive, or no geometry: background
        lit = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    vec4 mat = texelFetch(albedo, px, 0);
#ifdef PACKED
    vec3 n = oct_decode(texelFetch(normal_oct, px, 0).xy);
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, texelFetch(depth, px, 0).r, 1.0);
    vec3 p = w.xyz / w.w;
#else
    vec3 n = normalize(texelFetch(normal, px, 0).xyz);
    vec3 p = texelFetch(position, px, 0).xyz;
#endif
    vec3 v = normalize(frame.camera_pos.xyz - p);
    vec3 c = params.ambient * mat.rgb;
    for (int i = 0; i < params.lights; ++i) c += shade_point_light(point_light(i, frame.time), p, n, v, mat.rgb, mat.a, kShininess);
    lit = vec4(c, 1.0);
}
