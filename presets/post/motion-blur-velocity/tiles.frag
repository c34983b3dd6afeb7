#version 450
// Where the view moves at all, for dilate.frag (speed only, not the technique): lavapipe runs a
// window loop at full length even where every tap reads a zero velocity, but leaves a loop once
// every pixel of a block is done, so the dilation shortens its window to the pixel itself where
// nothing within reach moves. The window's longest velocity is then the pixel's own either way
// (no |v|^2 in it exceeds 0): the same result.
//   pass tiles (TILE_MAX):  the largest |v|^2 of the velocity buffer over each T x T tile,
//                           T = max(16, 2 radius) (0 exactly where all of the tile is still);
//   pass tiles_near:        the largest over the tile and its 8 neighbours. A window reaches
//                           radius <= T/2 pixels from its pixel, so it lies inside the 3 x 3
//                           tiles around the pixel's tile: one fetch tells dilate.frag.
layout(location = 0) out float motion;
#ifdef TILE_MAX
uniform sampler2D velocity;
void main() {
    int tile = max(16, 2 * params.radius);  // preset.toml's tile image sizes, dilate.frag's
    ivec2 t0 = ivec2(gl_FragCoord.xy) * tile, last = ivec2(frame.resolution.xy) - 1;
    float m = 0.0;
    for (int y = 0; y < tile; ++y)
        for (int x = 0; x < tile; ++x) {
            vec2 v = texelFetch(velocity, min(t0 + ivec2(x, y), last), 0).xy;
            m = max(m, dot(v, v));
        }
    motion = m;
}
#else
uniform sampler2D vel_tiles;
void main() {
    ivec2 t = ivec2(gl_FragCoord.xy), last = textureSize(vel_tiles, 0) - 1;
    float m = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) m = max(m, texelFetch(vel_tiles, clamp(t + ivec2(x, y), ivec2(0), last), 0).x);
    motion = m;
}
#endif
