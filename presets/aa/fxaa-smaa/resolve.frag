#version 450
// The chosen mode's output (002_644d46bdce7e5305.txt L1848-1857: none, FXAA, SMAA1x, SMAA T2x).
// SMAA T2x = SMAA1x on a frame jittered by (+0.25, -0.25) or (-0.25, +0.25) px, alternating,
// blended 50/50 with the previous frame's SMAA1x result ("alternative frame jitter and temporal
// alternative frame blending", L1855-1856): two sub-pixel positions per pixel over two frames.
// The scene here is static: the previous result needs no reprojection (SMAA's velocity
// weighting is left out and said so). Frame 0 has no previous result, and the first frame
// after a param change none that belongs to it (with crop, a moved region's new texels hold
// nothing): the current alone (accum_frame is 0 on both; in tests it equals frame.index).
layout(location = 0) out vec4 result;
uniform sampler2D color;
uniform sampler2D fxaa;
uniform sampler2D smaa;
uniform sampler2D smaa_prev;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (params.mode == MODE_NONE) result = texelFetch(color, p, 0);
    else if (params.mode == MODE_FXAA) result = texelFetch(fxaa, p, 0);
    else if (params.mode == MODE_SMAA1X || frame.accum_frame == 0) result = texelFetch(smaa, p, 0);
    else result = 0.5 * (texelFetch(smaa, p, 0) + texelFetch(smaa_prev, p, 0));
}
