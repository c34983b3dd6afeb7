// The Monte-Carlo estimator of the rendering equation for diffuse scenes: the GI family's
// reference (presets/gi/path-tracing-reference).
//
// Rendering equation (000_c9f7e5de708ecbb3.txt L4982-4989):
//     L(x, wo) = Le(x, wo) + integral over the hemisphere of L(x', -wi) f_r(x, wi, wo) cos(theta_i) dwi
// Neumann expansion (L5014-5037): L = L0 + L1 + L2 + ..., where L0 is the light arriving at x
// straight from the source and reflected to the eye, L1 the light after one more bounce, and so on.
//
// One path per sample, from the eye: at each vertex x_k (k = 0 the surface the eye sees)
//   - next-event estimation to the spot, which is a delta light, so its term is exact, not
//     sampled: (rho/pi) I(-l) max(0, n.l) / d^2 * V(x_k, light)            -> the term of L_k
//   - a bounce direction with the cosine density p(wi) = cos(theta)/pi; the estimator's weight
//     f_r cos / p = (rho/pi) cos / (cos/pi) = rho, so the throughput is multiplied by rho
//   - the bounce ray's miss brings the environment's radiance: that is light arriving at x_k
//     directly from a source too                                            -> the term of L_k
// so the light that reaches the eye after k + 1 reflections is L_k, and `bounces` = B keeps
// L0 .. LB (B = 0: direct only; B = 1: direct + one indirect bounce). No Russian roulette: the
// path length is fixed by `bounces`, which keeps every estimate's path count deterministic.
//
// Random numbers come from a hash of (pixel, sample index, vertex), so a path's k-th vertex is
// the same whichever terms are kept: L0 + L1 rendered separately equals the B = 1 image.
#ifndef PASSLAB_GI_PATHTRACE_GLSL
#define PASSLAB_GI_PATHTRACE_GLSL

#include "common/hash.glsl"
#include "gi/pathtrace_scene.glsl"
#include "gi/pathtrace_vertex.glsl"   // pathtrace_bounce, pathtrace_direct

// Which sequence of paths: another seed gives independent samples (a reference render that
// shares no path with the renders it judges). Callers may set it before tracing.
uint pathtrace_seed = 0u;

// Three uniform numbers in [0, 1) for vertex `vertex` of sample `sample_index` of `pixel`.
vec3 pathtrace_random(uvec2 pixel, uint sample_index, uint vertex) {
    return vec3(pcg3d(uvec3(pixel.x + (pathtrace_seed << 16u), pixel.y, sample_index * 64u + vertex))) * (1.0 / 4294967296.0);
}

// The radiance along the eye ray ro + t rd, the terms L_k for k = 0 .. bounces; keep >= 0 keeps
// only L_keep (the eye ray's miss, Le seen directly, belongs to L0). One call site of the ray
// query for the eye ray (k = -1) and the bounces: the traversal is inlined once, which halves
// llvmpipe's compile time of the shader (seconds under load; the frame watchdog counts it).
vec3 pathtrace_radiance(vec3 ro, vec3 rd, uvec2 pixel, uint sample_index, int bounces, int keep) {
    if (keep > bounces) return vec3(0.0);
    int last = keep >= 0 ? keep : bounces;
    vec3 environment = pathtrace_environment();
    vec3 radiance = vec3(0.0), throughput = vec3(1.0);
    PathtraceHit h;
    for (int k = -1; k <= last; ++k) {
        bool kept = keep < 0 || keep == max(k, 0);
        if (k >= 0) {
            if (kept) radiance += throughput * pathtrace_direct(h);
            // The last vertex's bounce ray only matters when the environment emits.
            if (k == last && all(equal(environment, vec3(0.0)))) break;
            vec3 weight;
            rd = pathtrace_bounce(h.n, pathtrace_random(pixel, sample_index, uint(k)).xy, h.albedo, weight);
            ro = h.p + PATHTRACE_OFFSET * h.n;
            throughput *= weight;
        }
        h = pathtrace_closest(ro, rd);
        if (!h.hit) {
            if (kept) radiance += throughput * environment;
            break;
        }
    }
    return radiance;
}

#endif
