#version 450
// The blur passes' input (not 002's; for a live frame rate on a CPU rasteriser):
//   resolution = full: src itself, texel for texel (the printed passes, unchanged);
//   resolution = half: one texel per 2x2 block of src (this target is view/2): the colour is
//     the 2x2 box mean (a small highlight keeps its energy instead of flickering in and out of
//     a one-texel pick), the CoC the smallest of the four, i.e. the nearest surface's (CoC is
//     bias + scale d, increasing with depth): no CoC averaged across a silhouette, and a near
//     object keeps its near blur.
// The CoC stays a fraction of the image height, so the blur passes run unchanged at either
// size: their steps (i + 0.5) / height are then half-res pixels, 2 view pixels each.
layout(location = 0) out vec4 hex_in;
uniform sampler2D src;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (params.resolution == RESOLUTION_FULL) {
        hex_in = texelFetch(src, p, 0);
        return;
    }
    vec4 a = texelFetch(src, 2 * p, 0), b = texelFetch(src, 2 * p + ivec2(1, 0), 0);
    vec4 c = texelFetch(src, 2 * p + ivec2(0, 1), 0), d = texelFetch(src, 2 * p + ivec2(1, 1), 0);
    hex_in = vec4(0.25 * (a.rgb + b.rgb + c.rgb + d.rgb), min(min(a.w, b.w), min(c.w, d.w)));
}
