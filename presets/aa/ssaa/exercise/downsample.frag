#version 450
// EXERCISE — the SSAA downsample (000_c9f7e5de708ecbb3.txt L3304-3310): the scene was rendered
// into `hi` at N x the resolution in each direction (L3306-3307); now "downsample final colour
// texture to target resolution using fullscreen shader; box filter" (L3308-3309).
// Fill in the two TODO blocks, then check your work against the reference:
//     passlab run   aa/ssaa --exercise presets/aa/ssaa/exercise   (live, hot reload)
//     passlab grade aa/ssaa --exercise presets/aa/ssaa/exercise   (the test cases)
// `hi` is rgba16f: it holds linear radiance, not sRGB-encoded values. texelFetch(hi, ivec2, 0)
// reads one sub-sample exactly; texture() with its linear filter blends four of them unless you
// aim at a texel's centre.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D hi;
void main() {
    int n = params.n;
    // TODO 1: this output pixel (gl_FragCoord.xy, which lies at the pixel's centre, x + 0.5)
    // covers exactly an N x N block of `hi` texels: the block of integer pixel p spans hi texels
    // N p ... N p + N - 1 on each axis. Find the first texel of the block (mind the + 0.5).

    // TODO 2: the box filter: the pixel's value is the mean of the N^2 sub-samples of its block,
    //     result = (1 / N^2) * sum over x, y in [0, N) of hi[block + (x, y)]
    // averaged as stored (linear), so that an edge pixel with k of its N^2 samples covered by a
    // white shape reads exactly k / N^2.
    result = vec4(0.0, 0.0, 0.0, 1.0);
}
