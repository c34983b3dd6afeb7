#version 450
// Tiled light culling (003_cfc3b5b225ddab3d.txt L906-922: "build the list of lights that
// affect each screen tile, not each object"). One thread per 16 x 16 tile: the axis-aligned box
// around the world positions of the tile's G-buffer samples, then every light whose sphere
// (centre, radius) meets that box goes into the tile's list. Tiles of sky have no samples and
// no lights. Bounding the actual samples (not the tile's whole frustum) is what depth-bounded
// tiles do: a tile with a near ball and a far floor gets a box spanning both, nothing more.
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
    vec3 lo = vec3(-1e30), hi = vec3(1e30);
    bool any_sample = false;
    for (int y = 0; y < kTile; ++y)
        for (int x = 0; x < kTile; ++x) {
            ivec2 p = t * kTile + ivec2(x, y);
            if (any(greaterThanEqual(p, ivec2(frame.resolution.xy)))) continue;
            if (texelFetch(normal, p, 0).w == 0.0) continue;
            vec3 w = texelFetch(position, p, 0).xyz;
            lo = min(lo, w), hi = max(hi, w), any_sample = true;
        }
    uint base = uint(t.y * tiles_xy.x + t.x) * uint(kMaxLights + 1), n = 0u;
    if (any_sample)
        for (int i = 0; i < params.lights && n < uint(kMaxLights); ++i) {
            PointLight l = point_light(i, frame.time);
            vec3 nearest = clamp(l.position, lo, hi);  // sphere-box test
            if (distance(nearest, l.position) <= l.radius) words[base + 1u + n++] = uint(i);
        }
    words[base] = n;
}
