// The luma post-process anti-aliasing judges edges by: Rec. 709 luminance of the sRGB-encoded
// colour (these filters run on the final image, so edges are judged as the display shows them).
#ifndef PASSLAB_AA_LUMA_GLSL
#define PASSLAB_AA_LUMA_GLSL
#include "common/color.glsl"
float aa_luma(vec3 c) { return luminance(linear_to_srgb(clamp(c, 0.0, 1.0))); }
#endif
