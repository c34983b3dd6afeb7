#version 450
// The circle of confusion as 002_644d46bdce7e5305.txt L1254-1287 computes it: linear in the
// depth-buffer value d,
//   f = 0.035 fovFactor,  A = f / diameter,
//   scale = A f F (zf - zn) / ((F - f) zn zf),   bias = A f (zn - F) / ((F - f) zn),
//   CoC(d) = (bias + scale d) / 0.0186          (0.0186: 35 mm widescreen film height)
// which is the thin-lens circle A f (z - F) / (z (F - f)) rewritten for d (Vulkan depth:
// 1/z = 1/zn - d (zf - zn)/(zn zf)). Negative in front of the focus, positive behind.
// Both forms live in passes/post/coc.glsl (coc_linear_in_depth, coc_thin_lens), shared with
// post/dof-hexagonal-bokeh and post/dof-ngon-bokeh.
// x: CoC (fraction of the image height); y: the thin-lens formula from z; z: |x - y|.
#include "post/coc.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 coc;
uniform sampler2D depth;
uniform sampler2D focus_state;
const float kNear = 0.1, kFar = 100.0;  // scene.frag's clip planes
void main() {
    float d = texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r;
    float F = texelFetch(focus_state, ivec2(0), 0).r;
    float c = coc_linear_in_depth(d, F, params.fov_factor, params.diameter, kNear, kFar);
    float z = view_depth_from_buffer(d, kNear, kFar);
    float thin = coc_thin_lens(z, F, params.fov_factor, params.diameter);
    coc = vec4(c, thin, abs(c - thin), 1.0);
}
