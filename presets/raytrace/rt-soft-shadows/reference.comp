#version 450
// rt-soft-shadows' test-only reference: the same integral, the fraction of the sun's cone seen
// from the point, by an independent route so that a wrong mapping in sun_disc.glsl cannot hide:
// jittered stratified points of the disc of radius tan(SUN) in the plane at distance 1 along L,
// d = normalize(L + x T + y B), each weighted by the solid angle its area subtends,
// d(omega) = cos^3(theta) dA, in a self-normalised mean:
//     V = sum_i w_i v_i / sum_i w_i,   w_i = cos^3(theta_i) = (1 + x_i^2 + y_i^2)^(-3/2)
// REF_RAYS rays per frame; over 256 frames each of the 64 x 32 strata of (r^2 / tan^2(SUN), phi /
// 2 pi) gets one jittered sample, 2048 in all. Accumulated like the method: the running means of
// sum w v and sum w in `ref_accum` (g, b), their ratio in r.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/shadow_scene.glsl"
#include "common/hash.glsl"
uniform sampler2D gpos;
uniform sampler2D gnrm;
uniform sampler2D ref_accum_prev;
layout(rgba32f) writeonly uniform image2D ref_accum;

// An orthonormal basis around the unit n without a helper axis (Duff et al. 2017, "Building an
// orthonormal basis, revisited", JCGT 6(1)): a different construction from sun_disc.glsl's.
void onb(vec3 n, out vec3 t, out vec3 b) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z), c = n.x * n.y * a;
    t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, imageSize(ref_accum)))) return;
    vec3 p, n;
    int object;
    vec2 sums = vec2(1.0);   // (sum w v, sum w) of this frame; the background is lit
    int k = frame.accum_frame;
    if (shadow_scene_surface(gpos, gnrm, px, p, n, object)) {
        vec3 l = shadow_light_dir(p), t, b;
        onb(l, t, b);
        float radius = tan(radians(params.sun_deg));
        sums = vec2(0.0);
        for (int i = 0; i < REF_RAYS; ++i) {
            int s = (k * REF_RAYS + i) % 2048;   // stratum: 64 along r^2, 32 along phi
            vec2 uv = (vec2(s % 64, s / 64) + hash_pcg3(vec3(px, float(s) + 1000.0)).xy) / vec2(64.0, 32.0);
            vec2 xy = radius * sqrt(uv.x) * vec2(cos(6.28318531 * uv.y), sin(6.28318531 * uv.y));
            float w = pow(1.0 + dot(xy, xy), -1.5);
            sums += w * vec2(shadow_scene_visibility(p, n, normalize(l + xy.x * t + xy.y * b)), 1.0);
        }
    }
    vec2 mean = k == 0 ? sums : mix(texelFetch(ref_accum_prev, px, 0).gb, sums, 1.0 / float(k + 1));
    imageStore(ref_accum, px, vec4(mean.x / mean.y, mean, 1.0));
}
