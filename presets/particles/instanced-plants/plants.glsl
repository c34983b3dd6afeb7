// Plants as parameterised instances (000_c9f7e5de708ecbb3.txt L219-225: "Plants created as
// parameterized instances"; L204-206: the geometry shader generates procedural geometry, "e.g.,
// growing plants"). An instance has a placement (where it stands, how it is turned) and a
// species index; the species alone decides the parameters, so two instances of one species grow
// the same plant. Shared by plant.vert, grow.geom and compare.comp.
#define PLANTS 32
#define SPECIES 4
#define GRID_X 8

struct PlPlant { float height, bend, width, leaf; int leaves; };

#include "common/hash.glsl"
// Uniform in [0, 1): integer hash only (common/hash.glsl, PCG3D), the same bits on every device.
float pl_plant_unit(uint a, uint k) { return float(pcg3d(uvec3(a, k, 11u)).x) * (1.0 / 4294967296.0); }

int plant_species(int instance) { return int(pcg3d(uvec3(uint(instance), 101u, 3u)).x % uint(SPECIES)); }

// The parameters: a function of the species only.
PlPlant plant_params(int species) {
    uint s = uint(species);
    return PlPlant(0.7 + 0.6 * pl_plant_unit(s, 0u),          // height
                   -0.35 + 0.7 * pl_plant_unit(s, 1u),        // bend of the stem's tip along x
                   0.035 + 0.025 * pl_plant_unit(s, 2u),       // stem half-width at the base
                   0.25 + 0.2 * pl_plant_unit(s, 3u),        // leaf length
                   2 + int(pcg3d(uvec3(s, 4u, 11u)).y % 5u)); // 2..6 leaves
}

// The placement: a function of the instance (grid cell, jitter, heading).
vec3 plant_root(int i) {
    uint u = uint(i);
    vec2 cell = vec2(i % GRID_X, i / GRID_X) - vec2(0.5 * (GRID_X - 1), 0.5 * (PLANTS / GRID_X - 1));
    return vec3(cell.x * 0.8 + 0.3 * (pl_plant_unit(u + 900u, 5u) - 0.5), 0.0, cell.y * 0.8 + 0.3 * (pl_plant_unit(u + 900u, 6u) - 0.5));
}
float plant_heading(int i) { return 6.2831853 * pl_plant_unit(uint(i) + 900u, 7u); }
