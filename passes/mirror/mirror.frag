#version 450
// The mirror's surface. A mirror reflects the fraction params.reflectivity and shows its own
// tint for the rest:  c = mix(tint, reflection, reflectivity).
// Stencil method (default): output (tint, 1 - reflectivity) and blend = "alpha" over the
// reflected scene already in the target: dst' = tint (1 - r) + dst r (000 L3874: "draw the
// mirror (transparent)").
// RTT (define RTT = the reflection texture's name): the reflection is looked up in the texture
// the mirrored camera rendered, at the mirror point projected by that camera (projective
// texturing, 000 L3946-3964), and mixed here; no blending.
// GBUFFER (a target name): the deferred form for SSR: own colour into hdr, normal + map there.
// MASK_TARGET (optional): 1 where the mirror covers the pixel (the stencil mask, readable).
#include "mirror/mirror.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
#ifdef MASK_TARGET
layout(location = 1) out vec4 MASK_TARGET;
#endif
#ifdef RTT
uniform sampler2D RTT;
#endif
#ifdef GBUFFER
layout(location = 1) out vec4 GBUFFER;  // deferred (SSR): xyz world normal, w reflection map
#endif
#ifndef VISIBLE
#define VISIBLE true
#endif
void main() {
    if (!(VISIBLE)) discard;
    vec3 tint = params.mirror_tint;
#ifdef RTT
    vec4 c = mirror_camera_view_proj() * vec4(v_world, 1.0);
    vec2 st = c.xy / c.w * 0.5 + 0.5;
#ifdef RTT_DISTORT
    st += RTT_DISTORT;  // an expression: offsets for fuzzy / rippled reflections (000 L3928)
#endif
    vec4 texel = texture(RTT, st);
    vec3 refl = texel.rgb;
    float refl_height = texel.a;  // what the RTT pass stored in alpha (the reflected point's height)
#ifdef RTT_FADE
    refl = mix(refl, tint, RTT_FADE);  // an expression in [0, 1] of refl_height: fade (000 L3927)
#endif
    hdr = vec4(mix(tint, refl, params.reflectivity), 1.0);
#elif defined(GBUFFER)
    // The lit image shows the mirror's own colour; the reflection map says how much of the
    // reflection a later pass mixes in: c = mix(lit, reflection, map) (000 L3990-3993).
    hdr = vec4(tint, 1.0);
    GBUFFER = vec4(normalize(v_normal), params.reflectivity);
#else
    hdr = vec4(tint, 1.0 - params.reflectivity);
#endif
#ifdef MASK_TARGET
    MASK_TARGET = vec4(1.0);
#endif
}
