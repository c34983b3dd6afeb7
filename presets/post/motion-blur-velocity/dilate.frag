#version 450
// Velocity dilation: the longest velocity within params.radius pixels along one axis (x with
// DILATE_X, else y). Run x then y, it is the longest in the square window. Background pixels
// next to a moving object take its velocity, so the gather in blur.frag smears the object over
// what it swept instead of stopping at its outline (000 L3634, "discontinuities at
// silhouettes"). With params.dilate off the velocity passes through unchanged.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 vel_out;
uniform sampler2D vel_in;
uniform sampler2D vel_near;  // tiles.frag: the largest |v|^2 within a tile of this one's tile

#ifdef DILATE_X
const ivec2 kAxis = ivec2(1, 0);
#else
const ivec2 kAxis = ivec2(0, 1);
#endif

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), size = ivec2(frame.resolution.xy);
    vec2 best = texelFetch(vel_in, px, 0).xy;
    int r = params.dilate ? params.radius : 0;
    // Speed (tiles.frag): nothing within reach moves, so the window's longest is the pixel's own.
    if (texelFetch(vel_near, px / max(16, 2 * params.radius), 0).x == 0.0) r = 0;
    for (int k = -r; k <= r; ++k) {
        ivec2 q = clamp(px + k * kAxis, ivec2(0), size - 1);
        vec2 v = texelFetch(vel_in, q, 0).xy;
        if (dot(v, v) > dot(best, best)) best = v;
    }
    vel_out = vec4(best, 0.0, 1.0);
}
