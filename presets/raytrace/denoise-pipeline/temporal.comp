#version 450
// Stage 2, temporal accumulation (000 L5818-5822): the reconstructed frame blended into its own
// history, reprojected through last frame's camera; the history is kept only where last
// frame saw the same surface there (else a disocclusion restarts it):
//   s_t = mix(s_(t-1), x_t, alpha),  alpha = max(1 / (n + 1), alpha_min),  n = history length
// 1 / (n + 1) is the running mean while the history is young; alpha_min keeps an exponential
// window so lighting that changes still shows within about 1 / alpha_min frames.
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/denoise.glsl"
uniform sampler2D spatial;
uniform sampler2D g_position;
uniform sampler2D g_normal;
uniform sampler2D g_position_prev;
uniform sampler2D g_normal_prev;
uniform sampler2D temporal_prev;
layout(rgba16f) writeonly uniform image2D temporal;  // rgb: mean, a: history length n

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = imageSize(temporal);
    if (any(greaterThanEqual(p, size))) return;
    vec3 x = texelFetch(spatial, p, 0).rgb;
    vec4 pos = texelFetch(g_position, p, 0);
    vec2 prev_uv = denoise_previous_uv(pos.xyz, (vec2(p) + 0.5) / vec2(size), frame.view_proj, frame.prev_view_proj);
    ivec2 prev_px = ivec2(floor(prev_uv * vec2(size)));
    bool inside = all(greaterThanEqual(prev_px, ivec2(0))) && all(lessThan(prev_px, size));
    bool keep = frame.accum_frame > 0u && pos.w > 0.0 && inside &&
                denoise_same_surface(pos.xyz, texelFetch(g_normal, p, 0).xyz, texelFetch(g_position_prev, prev_px, 0),
                                     texelFetch(g_normal_prev, prev_px, 0).xyz, 0.05);
    if (!keep) {
        imageStore(temporal, p, vec4(x, 1.0));
        return;
    }
    vec4 h = texture(temporal_prev, prev_uv);
    float alpha = max(1.0 / (h.a + 1.0), params.alpha_min);
    imageStore(temporal, p, vec4(mix(h.rgb, x, alpha), min(h.a + 1.0, 1024.0)));
}
