#version 450
// EXERCISE — tiled light culling (003_cfc3b5b225ddab3d.txt L906-922: "build the list of lights
// that affect each screen tile, not each object"). Fill in the three TODO blocks, then check:
//     passlab run   deferred/tiled-light-culling --exercise presets/deferred/tiled-light-culling/exercise
//     passlab grade deferred/tiled-light-culling --exercise presets/deferred/tiled-light-culling/exercise
// One thread per 16 x 16 tile. The G-buffer (pass 1) and the shading from the lists
// (shade.frag) are given: shade.frag reads words[base] as the tile's light count and the next
// words[base + 1 .. base + count] as light indices into point_light(i, frame.time)
// (passes/deferred/lights.glsl: each light has a centre l.position and a finite l.radius past
// which it adds exactly 0). A light left out of a list that reaches the tile darkens it.
#include "deferred/lights.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D position;
uniform sampler2D normal;
layout(std430) writeonly buffer tiles { uint words[]; };
const int kTile = 16, kMaxLights = 64;
void main() {
    ivec2 tiles_xy = (ivec2(frame.resolution.xy) + kTile - 1) / kTile;
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, tiles_xy))) return;
    // TODO 1: the tile's depth bounds, as an axis-aligned box [lo, hi] around the world
    // positions of its G-buffer samples (the "depth-bounded tile": a tile showing only floor
    // never gets the lights above the balls). Give lo and hi starting values such that the
    // first sample sets both, then grow the box by every sample of the tile - except sky
    // pixels, which stored no geometry (normal.w == 0) - and record in any_sample that there
    // was one.
    vec3 lo = vec3(0.0), hi = vec3(0.0);
    bool any_sample = false;
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) {
            ivec2 p = t * kTile + ivec2(x, y);
            if (any(greaterThanEqual(p, ivec2(frame.resolution.xy)))) continue;
            // (TODO 1 continued: this sample, texelFetch of normal and position at p)
        }
    uint base = uint(t.y * tiles_xy.x + t.x) * uint(kMaxLights + 1), n = 0u;
    if (any_sample)
        for (int i = 0; i < params.lights; ++i) {
            PointLight l = point_light(i, frame.time);
            // TODO 2: does light i's sphere (centre l.position, radius l.radius) meet the box
            // [lo, hi]? The sphere-box test: find the point of the box nearest to the centre and
            // compare its distance to the centre with the sphere (a light whose centre is
            // outside the box can still reach it).
            bool meets = false;
            // TODO 3: if it meets, append i to the tile's list (words[base + 1 + n], then count
            // it). The list has kMaxLights slots and no more: never write past them.
        }
    words[base] = n;
}
