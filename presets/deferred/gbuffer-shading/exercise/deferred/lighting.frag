#version 450
// EXERCISE — this file shadows passes/deferred/lighting.frag for deferred/gbuffer-shading only
// (both lighting passes, plain and PACKED, use it). Fill in the three TODO blocks.
//     passlab run   deferred/gbuffer-shading --exercise presets/deferred/gbuffer-shading/exercise
//     passlab grade deferred/gbuffer-shading --exercise presets/deferred/gbuffer-shading/exercise
// Pass 2 of deferred shading (000_c9f7e5de708ecbb3.txt L2900-2905, "fragment shader reads
// G-Buffers, perform shading"): a fullscreen pass reads the G-buffer and sums
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
    vec3 n = vec3(0.0, 1.0, 0.0), p = vec3(0.0);
#ifdef PACKED
    // TODO 2: the packed layout keeps no normal or position images. The normal is stored
    // octahedral-encoded in normal_oct (decode it with deferred/octahedral.glsl). The position
    // is rebuilt from the depth buffer: this pixel's normalised device coordinates are
    // (uv * 2 - 1, depth) - Vulkan: x, y in [-1, 1] with y down like uv, depth in [0, 1] as
    // stored - and frame.inv_view_proj takes clip space back to world space. Remember the
    // homogeneous divide.
#else
    // TODO 1: read this pixel's world normal and world position from the G-buffer images
    // written in pass 1 (normal.xyz, position.xyz; use texelFetch at px). fp16 storage leaves
    // the normal slightly off unit length: renormalise it.
#endif
    vec3 v = normalize(frame.camera_pos.xyz - p);
    // TODO 3: the shading the forward pass does per fragment, here once per pixel: an ambient
    // term params.ambient * albedo, plus for each of the params.lights lights
    // shade_point_light(point_light(i, frame.time), p, n, v, albedo, specular, kShininess)
    // (deferred/lights.glsl). The material image holds albedo in rgb, specular in a.
    vec3 c = mat.rgb;
    lit = vec4(c, 1.0);
}
