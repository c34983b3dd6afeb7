// Screen-space velocity for the motion-blur presets (post/motion-blur-velocity,
// post/motion-blur-reconstruction) (000_c9f7e5de708ecbb3.txt L3611: "current and previous model-view
// projection matrix form the velocity buffer"): where a point is now minus where it was one
// frame ago, in pixels.
//   v = (ndc_now - ndc_prev) / 2 * resolution
// Pixels, not NDC: the blur steps in texels, and NDC units differ in x and y when w != h.
#ifndef MB_VELOCITY_GLSL
#define MB_VELOCITY_GLSL
vec2 velocity_pixels(vec4 clip_now, vec4 clip_prev) {
    vec2 ndc_now = clip_now.xy / clip_now.w, ndc_prev = clip_prev.xy / clip_prev.w;
    return (ndc_now - ndc_prev) * 0.5 * frame.resolution.xy;
}
#endif
