// A brick wall texture for the image-synthesis presets: structure (mortar lines, half-brick
// offsets) that synthesis must keep, per-brick colours and per-texel grain that make every patch
// unique (PatchMatch's shifted-copy test needs one exact match per patch, so the wall must not be
// periodic). Values are quantised to 8 bits, so the rgba8 image stores them exactly and
// "this value occurs in the source" is an exact comparison.
#ifndef PASSLAB_IMAGE_BRICKS_GLSL
#define PASSLAB_IMAGE_BRICKS_GLSL
#include "common/hash.glsl"

// p: texel, brick: brick size in texels (w, h), seed: varies colours and grain.
vec3 image_bricks(ivec2 p, ivec2 brick, int seed) {
    int row = p.y / brick.y;
    int x = p.x + ((row & 1) == 1 ? brick.x / 2 : 0);   // odd rows shifted by half a brick
    ivec2 cell = ivec2(x / brick.x, row);
    ivec2 in_brick = ivec2(x % brick.x, p.y % brick.y);
    float grain = hash_pcg(vec3(p, float(seed) + 17.0)) - 0.5;
    vec3 c;
    if (in_brick.x < 2 || in_brick.y < 2) {
        c = vec3(0.62, 0.60, 0.56) + 0.06 * grain;          // mortar, 2 texels wide
    } else {
        vec3 h = hash_pcg3(vec3(cell, float(seed)));
        c = vec3(0.50 + 0.25 * h.x, 0.22 + 0.12 * h.y, 0.14 + 0.08 * h.z) + 0.10 * grain;
        // a darker lower edge gives each brick an orientation (up differs from down)
        if (in_brick.y == brick.y - 1) c *= 0.75;
    }
    return floor(clamp(c, 0.0, 1.0) * 255.0 + 0.5) / 255.0;
}
#endif
