#version 450
// Shades the mirror scene (scene.glsl) at the unreflected point v_world, seen from EYE (the
// view's eye, or its mirror image for a reflection: what the mirror shows is the real surface
// seen from the reflected eye). ALBEDO is an expression (kAlbedo[i] or the frame's colour).
// ALPHA (optional expression) goes to the alpha channel (RTT: the height above the mirror).
// Optional second target MASK_TARGET: 1 wherever this pass wrote a fragment (the leak test).
// Optional POINT_TARGET: second target = the world point shaded (which point a reflection shows).
// Optional GBUFFER: second target = world normal and the reflection map value (SSR).
#include "mirror/mirror.glsl"
#include "mirror/scene.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
#ifdef MASK_TARGET
layout(location = 1) out vec4 MASK_TARGET;
#endif
#ifdef POINT_TARGET
layout(location = 1) out vec4 POINT_TARGET;  // xyz the (unreflected) surface point, w = 1
#endif
#ifdef GBUFFER
layout(location = 1) out vec4 GBUFFER;  // xyz world normal, w reflection map
#endif
#ifndef EYE
#define EYE frame.camera_pos.xyz
#endif
#if !defined(ALBEDO) && defined(OBJECT)
#define ALBEDO kAlbedo[OBJECT]
#endif
#ifndef SPECULAR
#define SPECULAR params.specular
#endif
void main() {
    vec3 n = normalize(v_normal);
#ifndef ALPHA
#define ALPHA 1.0
#endif
    hdr = vec4(shade(v_world, n, EYE, ALBEDO, SPECULAR), ALPHA);
#ifdef MASK_TARGET
    MASK_TARGET = vec4(1.0);
#endif
#ifdef POINT_TARGET
    POINT_TARGET = vec4(v_world, 1.0);
#endif
#ifdef GBUFFER
    GBUFFER = vec4(n, 0.0);  // objects and frame do not reflect
#endif
}
