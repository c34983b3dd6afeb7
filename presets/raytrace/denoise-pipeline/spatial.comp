#version 450
// Stage 1, spatial reconstruction (000 L5812-5816): every pixel, holes included, becomes the
// normalised Gaussian-weighted mean of this frame's samples within `spatial_radius` pixels that
// lie on its own surface (raytrace/denoise.glsl). The 2x2 pattern puts a sample of every class
// in any window of radius >= 1; where none is on the surface (a one-pixel sliver), every
// sample of the window counts.
//
// One invocation per 2x2 block of pixels (issue #21: the same sums, fewer reads and taps).
// The four pixels' windows overlap: each tap of their union is read once and added to every
// pixel whose window holds it. With sampling = quarter, this frame's samples are the pixels
// 2 * block + c (raw.comp; c is the frame's pixel of each 2x2 block), every other row and
// column, at the same place in every block: away from the border (no clamping) the loop
// visits only those rows and columns, (r + 1)^2 taps for the four pixels instead of
// (2r + 1)^2 for each. Each pixel still adds its own taps in the original order (rows, then
// columns, ascending), so its sums are the one-pixel loop's. At the border the clamp can fold
// a hole's offset onto a sample: there every offset of the union is visited.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D raw;
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D spatial;

void main() {
    ivec2 base = 2 * ivec2(gl_GlobalInvocationID.xy), top = imageSize(spatial) - 1;
    if (any(greaterThan(base, top))) return;
    int r = params.spatial_radius;
    float sigma2 = 2.0 * max(0.25, 0.25 * float(r * r));  // Gaussian with sigma = r / 2
    // The block's pixels k = 0..3 at base + (k & 1, k >> 1): their surfaces (w = 0: sky, or
    // outside the image at an odd border, neither reconstructed).
    vec4 pos[4];
    vec3 n[4], sum[4], any_sum[4];
    float wsum[4], any_w[4];
    bool surface = false;
    for (int k = 0; k < 4; ++k) {
        ivec2 p = base + ivec2(k & 1, k >> 1);
        bool inside = all(lessThanEqual(p, top));
        pos[k] = inside ? texelFetch(g_position, p, 0) : vec4(0.0);
        n[k] = texelFetch(g_normal, min(p, top), 0).xyz;
        surface = surface || pos[k].w != 0.0;
        sum[k] = any_sum[k] = vec3(0.0), wsum[k] = any_w[k] = 0.0;
    }
    if (surface) {
        // Offsets from base: the union of the four windows is -r .. r + 1 on each axis.
        ivec2 first = ivec2(-r), stride = ivec2(1);
        if (params.sampling == SAMPLING_QUARTER && all(greaterThanEqual(base, ivec2(r))) && all(lessThanEqual(base + 1 + r, top))) {
            int chosen = int(frame.index % 4u);
            ivec2 c = ivec2(chosen & 1, chosen >> 1);
            first += (ivec2(r) + c) & 1;  // the first offset on a sample row / column (base is even)
            stride = ivec2(2);
        }
        for (int y = first.y; y <= r + 1; y += stride.y)
            for (int x = first.x; x <= r + 1; x += stride.x) {
                ivec2 q = clamp(base + ivec2(x, y), ivec2(0), top);
                vec4 s = texelFetch(raw, q, 0);
                if (s.a == 0.0) continue;  // a hole (or a sky pixel: no ray)
                vec4 qp = texelFetch(g_position, q, 0);
                vec3 qn = texelFetch(g_normal, q, 0).xyz;
                for (int k = 0; k < 4; ++k) {
                    ivec2 d = ivec2(x, y) - ivec2(k & 1, k >> 1);  // the tap's offset from pixel k
                    if (any(greaterThan(abs(d), ivec2(r)))) continue;
                    float g = exp(-float(d.x * d.x + d.y * d.y) / sigma2);
                    float w = g * qp.w * denoise_geometry_weight(pos[k].xyz, n[k], qp.xyz, qn, 0.05);
                    sum[k] += w * s.rgb, wsum[k] += w;
                    any_sum[k] += g * s.rgb, any_w[k] += g;
                }
            }
    }
    for (int k = 0; k < 4; ++k) {
        ivec2 p = base + ivec2(k & 1, k >> 1);
        if (any(greaterThan(p, top))) continue;
        vec3 c = wsum[k] > 0.0 ? sum[k] / wsum[k] : (any_w[k] > 0.0 ? any_sum[k] / any_w[k] : vec3(0.0));
        if (pos[k].w == 0.0) c = texelFetch(raw, p, 0).rgb;  // sky: known every frame, nothing to reconstruct
        imageStore(spatial, p, vec4(c, 1.0));
    }
}
