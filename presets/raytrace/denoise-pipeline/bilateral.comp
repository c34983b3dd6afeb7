#version 450
// Stage 3, bilateral clean-up (000 L5824-5827): a cross-bilateral filter on the accumulated
// image, w = Gaussian(distance) * same surface (G-buffer) * exp(-|c_q - c_p|^2 / (2 s^2)) with
// s = range_sigma (lum(c_p) + 0.05): smooths the remaining blotches, keeps shadow edges whose
// step is large against s. Normalised: a constant stays constant.
//
// One invocation per 2x2 block of pixels (issue #21): the four 5x5 windows overlap, so each of
// the 6x6 texels of their union is read once (colour, position, normal) and added to every
// pixel whose window holds it: 36 reads of each image for four pixels instead of 100. Each
// pixel adds its taps in the one-pixel loop's order (rows, then columns): the same sums.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D temporal;
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D bilateral;

void main() {
    ivec2 base = 2 * ivec2(gl_GlobalInvocationID.xy), top = imageSize(bilateral) - 1;
    if (any(greaterThan(base, top))) return;
    // The block's pixels k = 0..3 at base + (k & 1, k >> 1) (w = 0: sky, or outside the image
    // at an odd border: no filtering).
    vec3 c0[4], n[4], sum[4];
    vec4 pos[4];
    float two_s2[4], wsum[4];
    bool surface = false;
    for (int k = 0; k < 4; ++k) {
        ivec2 p = min(base + ivec2(k & 1, k >> 1), top);
        c0[k] = texelFetch(temporal, p, 0).rgb;
        pos[k] = all(lessThanEqual(base + ivec2(k & 1, k >> 1), top)) ? texelFetch(g_position, p, 0) : vec4(0.0);
        n[k] = texelFetch(g_normal, p, 0).xyz;
        float s = params.range_sigma * (dot(c0[k], vec3(0.2126, 0.7152, 0.0722)) + 0.05);
        two_s2[k] = 2.0 * s * s;
        surface = surface || pos[k].w != 0.0;
        sum[k] = vec3(0.0), wsum[k] = 0.0;
    }
    if (surface)
        for (int y = -2; y <= 3; ++y)
            for (int x = -2; x <= 3; ++x) {
                ivec2 q = clamp(base + ivec2(x, y), ivec2(0), top);
                vec3 c = texelFetch(temporal, q, 0).rgb;
                vec4 qp = texelFetch(g_position, q, 0);
                vec3 qn = texelFetch(g_normal, q, 0).xyz;
                for (int k = 0; k < 4; ++k) {
                    ivec2 o = ivec2(x, y) - ivec2(k & 1, k >> 1);  // the tap's offset from pixel k
                    if (any(greaterThan(abs(o), ivec2(2)))) continue;
                    vec3 d = c - c0[k];
                    float w = exp(-float(o.x * o.x + o.y * o.y) / 4.5) * exp(-dot(d, d) / two_s2[k]) * qp.w *
                              denoise_geometry_weight(pos[k].xyz, n[k], qp.xyz, qn, 0.05);
                    sum[k] += w * c, wsum[k] += w;
                }
            }
    for (int k = 0; k < 4; ++k) {
        ivec2 p = base + ivec2(k & 1, k >> 1);
        if (any(greaterThan(p, top))) continue;
        // The centre has w = 1: wsum >= 1 on a surface; the sky keeps its colour.
        imageStore(bilateral, p, vec4(pos[k].w == 0.0 ? c0[k] : sum[k] / wsum[k], 1.0));
    }
}
