#version 450
// EXERCISE — the bright pass of bloom (002_644d46bdce7e5305.txt L698-704 and the snippet at
// L854-869; 000_c9f7e5de708ecbb3.txt L3088-3091, "before Gaussian filtering: modify rendered
// texture intensities"). This file shadows passes/post/bright_pass.frag for post/bloom only.
// One texel of the quarter-resolution `bright` image per 4x4 block of the HDR scene `hdr`;
// only what exceeds params.threshold may bloom. Fill in the two TODO blocks, then check:
//     passlab run   post/bloom --exercise presets/post/bloom/exercise   (live, hot reload)
//     passlab grade post/bloom --exercise presets/post/bloom/exercise   (the test cases)
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 bright;
uniform sampler2D hdr;
void main() {
    // The block's first texel, and the last valid texel (a view not divisible by 4 has partial
    // blocks at its right and top: clamp the reads there).
    ivec2 base = ivec2(gl_FragCoord.xy) * 4, last = ivec2(frame.resolution.xy) - 1;

    // TODO 1: the mean radiance of the 4x4 block of hdr that starts at `base` (L860-866: every
    // one of its 16 texels, read with texelFetch, clamped to `last`).
    vec3 mean = vec3(0.0);

    // TODO 2: keep only what exceeds the threshold, never below 0, doubled (L698-704, L867):
    //     bright = max(0, mean - threshold) * 2
    // With threshold 1.0 the whole 0..1 range stays unbloomed (L702). Threshold the block's
    // mean, not its single texels.
    bright = vec4(mean, 1.0);
}
