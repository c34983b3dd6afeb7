// EXERCISE — shadows passes/post/coc.glsl: the circle of confusion from depth, the two forms in
// 002_644d46bdce7e5305.txt. Fill in TODO 1 (and TODO 2, 3 in gather.frag), then grade:
//     passlab grade post/dof-coc-gather --exercise presets/post/dof-coc-gather/exercise
#ifndef PASSLAB_COC_GLSL
#define PASSLAB_COC_GLSL

// 002 L1254-1287 (Supraleiter's compute shader): the CoC is linear in the depth-buffer value d,
//   f = 0.035 fovFactor,  A = f / diameter,
//   scale = A f F (zf - zn) / ((F - f) zn zf),   bias = A f (zn - F) / ((F - f) zn)
//   CoC(d) = (bias + scale d) / 0.0186      (a fraction of the 18.6 mm film height = of the image)
// with uClipPlaneDepthOfFieldConstants = (zf - zn, zn zf, zn, zf) (L1287). This is the thin-lens
// circle A f (z - F) / (z (F - f)) for Vulkan's d = zf (z - zn) / (z (zf - zn)): negative in
// front of the focus F, positive behind.
const float kFilmHeight = 0.0186;  // 35 mm widescreen film, 21.95 mm x 18.6 mm
float coc_linear_in_depth(float d, float focus, float fov_factor, float diameter, float zn, float zf) {
    float f = 0.035 * fov_factor, A = f / diameter;
    // TODO 1: 002 L1254-1287. The CoC is linear in d, the value the depth buffer holds (not the
    // view depth z: that is what makes it one multiply-add per pixel):
    //     scale = A f F (zf - zn) / ((F - f) zn zf),   bias = A f (zn - F) / ((F - f) zn)
    //     CoC(d) = (bias + scale d) / kFilmHeight       (F = focus)
    // Negative in front of the focus, positive behind, 0 at z = F.
    return 0.0;
}

// The Vulkan depth-buffer value of a view depth z > 0 (what a scene pass writes for the above).
float depth_buffer_value(float z, float zn, float zf) { return zf * (z - zn) / (z * (zf - zn)); }

// Its inverse: the view depth z of a depth-buffer value d (1/z = 1/zn - d (zf - zn)/(zn zf)).
float view_depth_from_buffer(float d, float zn, float zf) { return zn * zf / (zf - d * (zf - zn)); }

// The thin-lens circle the linear form above is a rewrite of, from the view depth z (a fraction
// of the film height too): A f (z - F) / (z (F - f)) / 0.0186. A test reference, not 002's code.
float coc_thin_lens(float z, float focus, float fov_factor, float diameter) {
    float f = 0.035 * fov_factor, A = f / diameter;
    return A * f * (z - focus) / (z * (focus - f)) / kFilmHeight;
}

// 002 L1530-1534 (the 64k intro's shader): the blur radius in pixels, f the focal length, d the
// focal plane and o the depth, all in mm:
//   a = o f / (o - f), b = d f / (d - f), c = (d - f) / (d fstop CoC), blur = |a - b| c
// simplified as printed: blur = |f^2 (d - o) / ((d - f)(o - f))| (d - f) / (d fstop CoC).
// 0 at o = d; CoC = 0.03 mm (35 mm film).
float blur_64k(float f, float d, float o, float fstop, float coc) {
    return (abs(((f * f) * (d - o)) / ((d - f) * (o - f))) * (d - f)) / (d * fstop * coc);
}
#endif
