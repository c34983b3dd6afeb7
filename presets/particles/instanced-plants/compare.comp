#version 450
// Test-only: the per-instance patches (grow.geom with PATCH) compared tile against tile, for
// every pair of instances. Same species (identical parameters): the two patches must be equal
// pixel for pixel. Different species: they must differ somewhere (else the check is vacuous).
layout(local_size_x = 64) in;
#include "plants.glsl"
uniform sampler2D patches;
layout(std430) buffer Result {
    uint same_pairs;        // pairs of instances with one species
    uint same_mismatch;     // pixels that differ between such a pair's patches (must be 0)
    uint other_pairs;       // pairs of different species
    uint other_differing;   // of those, pairs whose patches differ in >= 1 pixel (must be all)
} result;
void main() {
    uint pair = gl_GlobalInvocationID.x;   // one thread per ordered pair i < j
    int i = int(pair) / PLANTS, j = int(pair) % PLANTS;
    if (i >= PLANTS || j <= i) return;
    ivec2 tile = textureSize(patches, 0) / ivec2(GRID_X, PLANTS / GRID_X);
    ivec2 oi = tile * ivec2(i % GRID_X, i / GRID_X), oj = tile * ivec2(j % GRID_X, j / GRID_X);
    uint differ = 0u;
    for (int y = 0; y < tile.y; ++y)
        for (int x = 0; x < tile.x; ++x)
            if (texelFetch(patches, oi + ivec2(x, y), 0) != texelFetch(patches, oj + ivec2(x, y), 0)) ++differ;
    bool same = plant_species(i) == plant_species(j);
    if (same) { atomicAdd(result.same_pairs, 1u); atomicAdd(result.same_mismatch, differ); }
    else { atomicAdd(result.other_pairs, 1u); if (differ > 0u) atomicAdd(result.other_differing, 1u); }
}
