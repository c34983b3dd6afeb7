#version 450
// Pass 1a of radiosity (000_c9f7e5de708ecbb3.txt L5066-5072): the form factors, by ray casting.
//
// F_ij, the share of the light leaving patch i that arrives at patch j, is the probability that
// a ray from a uniformly chosen point of i, in a cosine-distributed direction, hits j first. So
// RAD_RAYS such rays per patch estimate a whole row of F at once, visibility included, and the
// gather needs only "which patch did ray k of patch i hit": hits[i * RAD_RAYS + k] = j, -1 when
// the ray leaves the scene (the open front), -2 when the sample point lies inside a block (a
// floor point under a block: not part of the visible surface, so not counted). In a closed
// scene every counted ray hits a patch, so every row sums to exactly 1 (the closed-box test).
layout(local_size_x = 64) in;

#include "gi/radiosity_trace.glsl"
#include "common/hash.glsl"
#include "common/sampling.glsl"

layout(std430) writeonly buffer Hits { int hit[]; } hits;

void main() {
    int k = int(gl_GlobalInvocationID.x), p = int(gl_GlobalInvocationID.y);
    if (k >= RAD_RAYS || p >= RAD_PATCHES) return;
    int surface = radiosity_surface_of_patch(p);
    RadSurface s = radiosity_surface(surface);
    int walls = params.closed ? RAD_WALLS : CORNELL_WALLS;
    if (p >= RAD_LIVE_PATCHES || (s.mesh == 0 && s.instance >= walls)) {
        hits.hit[p * RAD_RAYS + k] = -2;  // block bottoms and the absent front wall gather nothing
        return;
    }
    // A jittered point of the patch and a jittered stratum of the cosine hemisphere
    // (sin^2 theta = u, phi = 2 pi v: density cos(theta) / pi, every ray the same weight).
    vec3 h = hash_pcg3(vec3(p, k, 7));
    int local = p - s.first;
    // Kept 1e-3 off the surface's border: a point on the seam with the next wall would start its
    // ray closer to that wall than the trace's tmin and let it slip out through the corner.
    vec2 ab = clamp((vec2(local % s.n, local / s.n) + h.xy) / float(s.n), 1e-3, 1.0 - 1e-3);
    mat4 m = radiosity_world_from_object(s);
    vec3 origin = (m * vec4(radiosity_object_point(s, ab), 1.0)).xyz;
    vec3 n = radiosity_world_normal(s);
    int side = int(sqrt(float(RAD_RAYS)));
    vec2 uv = (vec2(k % side, k / side) + hash_pcg3(vec3(k, p, 11)).xy) / float(side);
    float sin_t = sqrt(uv.x), cos_t = sqrt(max(0.0, 1.0 - uv.x)), phi = 6.28318530718 * uv.y;
    vec3 dir = basis_from_normal(n) * vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
    hits.hit[p * RAD_RAYS + k] = radiosity_trace_patch(origin, dir, walls);
}
