#version 450
// The reference: the texture averaged over the pixel's square, ref_grid x ref_grid stratified
// sub-pixel positions (16 x 16 = 256 per pixel by default), each ray-cast to the plane and
// sampled bilinearly from level 0. This is the box filter over the true footprint that every
// real-time filter approximates. Alpha = the fraction of sub-samples on the plane.
// Progressive in the live view: with ref_split = s the grid is drawn as s^2 interleaved
// sub-grids, one per frame (frame k takes the points (i, j) with i mod s, j mod s = k's digits),
// their sums and hit counts add up in reference_acc, and from frame s^2 on (the whole grid seen)
// the sum is kept as it is: the same box filter as all ref_grid^2 samples in one frame, at 1/s^2
// of the cost per frame for s^2 frames, then none. Any change of view or param restarts it
// (frame.accum_frame). ref_split = 1: every sample in the frame (what the tests run).
#include "ground.glsl"
layout(location = 0) out vec4 reference_out;
layout(location = 1) out vec4 reference_acc;   // sum of the samples' rgb, number of hits
uniform sampler2D tex_level0;
uniform sampler2D reference_acc_prev;
#include "strips.glsl"
void main() {
    reference_acc = vec4(0.0);
    if (!filter_needed(SHOW_REFERENCE, gl_FragCoord.x)) { reference_out = vec4(0.0); return; }
    // A pixel whose four corners all look above the horizon has no sample on the plane: the
    // height of the ray's far-plane point above the eye, w.y / w.w - o.y (the sign of d.y in
    // ground_uv), is affine in the pixel position, so its minimum over the pixel is at a corner.
    // 1e-3 (far-plane units, ~100 away) is far above the rounding of either evaluation, so the
    // pixels skipped are exactly those whose every sample ground_uv refuses (the loop would
    // give the same vec4(0); on lavapipe it is skipped only where a whole group of pixels is sky).
    float lowest = 1e30;
    for (int c = 0; c < 4; ++c) {
        vec2 ndc = (floor(gl_FragCoord.xy) + vec2(c & 1, c >> 1)) * frame.resolution.zw * 2.0 - 1.0;
        vec4 w = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
        lowest = min(lowest, w.y / w.w - frame.camera_pos.y);
    }
    if (lowest > 1e-3) { reference_out = vec4(0.0); return; }
    int n = params.ref_grid;
    int s = clamp(params.ref_split, 1, n);
    int k = int(frame.accum_frame);
    vec4 acc = k > 0 ? texelFetch(reference_acc_prev, ivec2(gl_FragCoord.xy), 0) : vec4(0.0);
    if (k < s * s) {  // this frame's sub-grid: i = s a + (k mod s), j = s b + (k / s)
        ivec2 d = ivec2(k % s, k / s);
        vec2 corner = floor(gl_FragCoord.xy);
        for (int j = d.y; j < n; j += s)
            for (int i = d.x; i < n; i += s) {
                vec2 t;
                if (ground_uv(corner + (vec2(i, j) + 0.5) / float(n), t)) acc += vec4(textureLod(tex_level0, t, 0.0).rgb, 1.0);
            }
    }
    reference_acc = acc;
    // until the whole grid is seen, the mean of the samples drawn so far (hits over drawn points)
    float drawn = float(n * n) * float(min(k + 1, s * s)) / float(s * s);
    reference_out = acc.w > 0.0 ? vec4(acc.rgb / acc.w, acc.w / drawn) : vec4(0.0);
}
