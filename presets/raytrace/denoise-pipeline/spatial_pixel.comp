#version 450
// Stage 1, spatial reconstruction (000 L5812-5816): every pixel, holes included, becomes the
// normalised Gaussian-weighted mean of this frame's samples within `spatial_radius` pixels that
// lie on its own surface (raytrace/denoise.glsl). The 2x2 pattern puts a sample of every class
// in any window of radius >= 1; where none is on the surface (a one-pixel sliver), every
// sample of the window counts.
// This is the plain form, one pixel per invocation; the live pass (spatial.comp) computes the
// same sums for a 2x2 block per invocation. Test-only (check_blocks): the two must agree exactly.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D raw;
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D spatial;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), top = imageSize(spatial) - 1;
    if (any(greaterThan(p, top))) return;
    vec4 pos = texelFetch(g_position, p, 0);
    if (pos.w == 0.0) {  // sky: known every frame, nothing to reconstruct
        imageStore(spatial, p, vec4(texelFetch(raw, p, 0).rgb, 1.0));
        return;
    }
    vec3 n = texelFetch(g_normal, p, 0).xyz;
    int r = params.spatial_radius;
    float sigma2 = 2.0 * max(0.25, 0.25 * float(r * r));  // Gaussian with sigma = r / 2
    vec3 sum = vec3(0.0), any_sum = vec3(0.0);
    float wsum = 0.0, any_w = 0.0;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
            ivec2 q = clamp(p + ivec2(x, y), ivec2(0), top);
            vec4 s = texelFetch(raw, q, 0);
            if (s.a == 0.0) continue;  // a hole
            float g = exp(-float(x * x + y * y) / sigma2);
            vec4 qp = texelFetch(g_position, q, 0);
            float w = g * qp.w * denoise_geometry_weight(pos.xyz, n, qp.xyz, texelFetch(g_normal, q, 0).xyz, 0.05);
            sum += w * s.rgb, wsum += w;
            any_sum += g * s.rgb, any_w += g;
        }
    vec3 c = wsum > 0.0 ? sum / wsum : (any_w > 0.0 ? any_sum / any_w : vec3(0.0));
    imageStore(spatial, p, vec4(c, 1.0));
}
