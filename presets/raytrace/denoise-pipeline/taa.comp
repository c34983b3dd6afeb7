#version 450
// Stage 4, temporal anti-aliasing (000 L5829-5833; the TAA of 000 L3385-3554, as presets/aa/taa):
// the jittered, cleaned frame blended into the reprojected TAA history after clipping that
// history to the min/max of the current 3x3 neighbourhood (000 L3528-3532), alpha = taa_alpha.
// Averages the jittered sub-pixel positions (anti-aliasing) and the noise left after the
// clean-up; the clip keeps a moving edge from ghosting. A constant stays constant: the clip
// range is [c, c] and the blend a convex combination.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D bilateral;
uniform sampler2D g_position;
uniform sampler2D taa_prev;
layout(rgba16f) writeonly uniform image2D taa;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = imageSize(taa), top = size - 1;
    if (any(greaterThan(p, top))) return;
    vec3 x = texelFetch(bilateral, p, 0).rgb, lo = x, hi = x;
    for (int k = 0; k < 9; ++k) {
        vec3 c = texelFetch(bilateral, clamp(p + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), top), 0).rgb;
        lo = min(lo, c), hi = max(hi, c);
    }
    vec4 pos = texelFetch(g_position, p, 0);
    // The sky has no point to reproject: its history is read where it is.
    vec2 pixel_uv = (vec2(p) + 0.5) / vec2(size);
    vec2 prev_uv = pos.w > 0.0 ? denoise_previous_uv(pos.xyz, pixel_uv, frame.view_proj, frame.prev_view_proj) : pixel_uv;
    bool inside = all(greaterThanEqual(prev_uv, vec2(0.0))) && all(lessThanEqual(prev_uv, vec2(1.0)));
    if (frame.accum_frame == 0u || !inside) {
        imageStore(taa, p, vec4(x, 1.0));
        return;
    }
    vec3 h = clamp(texture(taa_prev, prev_uv).rgb, lo, hi);
    imageStore(taa, p, vec4(mix(h, x, params.taa_alpha), 1.0));
}
