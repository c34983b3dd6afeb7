#version 450
// Stage 3, bilateral clean-up (000 L5824-5827): a cross-bilateral filter on the accumulated
// image, w = Gaussian(distance) * same surface (G-buffer) * exp(-|c_q - c_p|^2 / (2 s^2)) with
// s = range_sigma (lum(c_p) + 0.05): smooths the remaining blotches, keeps shadow edges whose
// step is large against s. Normalised: a constant stays constant.
// This is the plain form, one pixel per invocation; the live pass (bilateral.comp) computes the
// same sums for a 2x2 block per invocation. Test-only (check_blocks): the two must agree exactly.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D temporal;
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba16f) writeonly uniform image2D bilateral;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), top = imageSize(bilateral) - 1;
    if (any(greaterThan(p, top))) return;
    vec3 c0 = texelFetch(temporal, p, 0).rgb;
    vec4 pos = texelFetch(g_position, p, 0);
    if (pos.w == 0.0) {
        imageStore(bilateral, p, vec4(c0, 1.0));
        return;
    }
    vec3 n = texelFetch(g_normal, p, 0).xyz;
    float s = params.range_sigma * (dot(c0, vec3(0.2126, 0.7152, 0.0722)) + 0.05);
    vec3 sum = vec3(0.0);
    float wsum = 0.0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = clamp(p + ivec2(x, y), ivec2(0), top);
            vec3 c = texelFetch(temporal, q, 0).rgb, d = c - c0;
            vec4 qp = texelFetch(g_position, q, 0);
            float w = exp(-float(x * x + y * y) / 4.5) * exp(-dot(d, d) / (2.0 * s * s)) * qp.w *
                      denoise_geometry_weight(pos.xyz, n, qp.xyz, texelFetch(g_normal, q, 0).xyz, 0.05);
            sum += w * c, wsum += w;
        }
    imageStore(bilateral, p, vec4(sum / wsum, 1.0));  // the centre has w = 1: wsum >= 1
}
