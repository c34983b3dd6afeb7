// The two per-vertex terms of the path tracer's estimator (passes/gi/pathtrace.glsl): the
// cosine-weighted bounce with its weight, and next-event estimation to the spot. In a file of
// their own because they are the exercise of presets/gi/path-tracing-reference
// (exercise/gi/pathtrace_vertex.glsl shadows this file).
//
// Rendering equation (000_c9f7e5de708ecbb3.txt L4982-4989):
//     L(x, wo) = Le(x, wo) + integral over the hemisphere of L(x', -wi) f_r(x, wi, wo) cos(theta_i) dwi
// estimated at each vertex by one direction wi drawn with density p: L(x', -wi) f_r cos / p.
#ifndef PASSLAB_GI_PATHTRACE_VERTEX_GLSL
#define PASSLAB_GI_PATHTRACE_VERTEX_GLSL

#include "common/sampling.glsl"
#include "gi/pathtrace_scene.glsl"

const float PATHTRACE_PI = 3.14159265358979;

// A direction around the unit normal n with the density p(wi) = cos(theta) / pi, from two uniform
// numbers (Malley's method: uniform on the disk, lifted onto the hemisphere), and its weight
// f_r cos(theta) / p(wi) for a Lambertian surface of albedo rho, f_r = rho / pi.
vec3 pathtrace_bounce(vec3 n, vec2 u, vec3 rho, out vec3 weight) {
    float sin_t = sqrt(u.x), cos_t = sqrt(max(0.0, 1.0 - u.x)), phi = 2.0 * PATHTRACE_PI * u.y;
    vec3 local = vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
    weight = rho;
    return basis_from_normal(n) * local;
}

// Next-event estimation at a surface point: the radiance the spot light reflects towards the eye,
// (rho/pi) I(-l) max(0, n.l) / d^2 times the shadow ray's visibility (000_c9f7e5de708ecbb3.txt
// L4982-4989 with a delta light: the integral collapses to its one direction).
vec3 pathtrace_direct(PathtraceHit h) {
    if (pathtrace_scene_id != PATHTRACE_CORNELL) return vec3(0.0);
    vec3 e = cornell_light_irradiance(h.p, h.n);
    vec3 o = h.p + PATHTRACE_OFFSET * h.n;
    if (pathtrace_occluded(o, CORNELL_LIGHT_POS - o)) return vec3(0.0);
    return h.albedo * e;  // rho times the irradiance
}

#endif
