#version 450
// The reference: the texture averaged over the pixel's square, ref_grid x ref_grid stratified
// sub-pixel positions (16 x 16 = 256 per pixel by default), each ray-cast to the plane and
// sampled bilinearly from level 0. This is the box filter over the true footprint that every
// real-time filter approximates. Alpha = the fraction of sub-samples on the plane.
#include "ground.glsl"
layout(location = 0) out vec4 reference_out;
uniform sampler2D tex_level0;
#include "strips.glsl"
void main() {
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
    vec3 sum = vec3(0.0);
    float hits = 0.0;
    vec2 corner = floor(gl_FragCoord.xy);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            vec2 t;
            if (ground_uv(corner + (vec2(i, j) + 0.5) / float(n), t)) {
                sum += textureLod(tex_level0, t, 0.0).rgb;
                hits += 1.0;
            }
        }
    reference_out = hits > 0.0 ? vec4(sum / hits, hits / float(n * n)) : vec4(0.0);
}
