// EXERCISE: screen-space velocity for the motion-blur presets (000_c9f7e5de708ecbb3.txt L3611:
// "current and previous model-view projection matrix form the velocity buffer"): where a point
// is now minus where it was one frame ago, in pixels.
#ifndef MB_VELOCITY_GLSL
#define MB_VELOCITY_GLSL
vec2 velocity_pixels(vec4 clip_now, vec4 clip_prev) {
    // TODO 1: the velocity in pixels per frame (000 L3608-3613). Divide each clip position by
    // its w to get normalised device coordinates (ndc in [-1, 1] across the image), take the
    // difference now - previous, and convert NDC units to pixels: the image spans 2 NDC units
    // over frame.resolution.xy pixels, so
    //   v = (ndc_now - ndc_prev) / 2 * resolution.
    // Pixels, not NDC: the blur steps in texels, and NDC units differ in x and y when w != h.
    return vec2(0.0);  // replace
}
#endif
