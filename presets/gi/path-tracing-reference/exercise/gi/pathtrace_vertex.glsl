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
    // TODO 1 (000_c9f7e5de708ecbb3.txt L4982-4989: the reflected light is the integral over the
    // hemisphere of L(x, wi) f_r cos(theta_i) dwi; Monte Carlo estimates it by one direction wi
    // drawn with density p as L(x, wi) f_r cos(theta_i) / p(wi)).
    // Draw wi around n with the cosine density p(wi) = cos(theta) / pi, e.g. Malley's method
    // (a uniform point on the unit disk lifted onto the hemisphere: sin^2(theta) = u.x,
    // phi = 2 pi u.y, in the frame basis_from_normal(n) of common/sampling.glsl), and set
    // weight = f_r cos(theta) / p(wi) for the Lambertian f_r = rho / pi. What does it simplify to?
    weight = vec3(0.0);
    return n;
}

// Next-event estimation at a surface point: the radiance the spot light reflects towards the eye,
// (rho/pi) I(-l) max(0, n.l) / d^2 times the shadow ray's visibility (000_c9f7e5de708ecbb3.txt
// L4982-4989 with a delta light: the integral collapses to its one direction).
vec3 pathtrace_direct(PathtraceHit h) {
    if (pathtrace_scene_id != PATHTRACE_CORNELL) return vec3(0.0);
    // TODO 2 (L5014-5019, L0: "direct lighting arriving at point x"). The spot is a delta light:
    // the integral of L f_r cos dwi collapses onto its one direction, so this term is exact:
    //     L0 = f_r * I(-l) max(0, n.l) / d^2 * V(x, light),   f_r = rho / pi
    // cornell_light_irradiance(h.p, h.n) gives I(-l) max(0, n.l) / d^2 (gi/cornell.glsl).
    // V: a shadow ray with pathtrace_occluded(origin, CORNELL_LIGHT_POS - origin) from an origin
    // PATHTRACE_OFFSET off the surface along h.n (a ray from the surface itself hits it).
    return vec3(0.0);
}

#endif
