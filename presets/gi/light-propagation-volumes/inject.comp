#version 450
// Injection (002_644d46bdce7e5305.txt L2567-2570; 000_c9f7e5de708ecbb3.txt L5130-5134 "light
// propagation (= irradiance) volumes"): virtual point lights where the spot's light first lands,
// 65536 of them in jittered strata of the cone (as photon mapping shoots its photons), each a
// Lambertian emitter of the flux it reflects, Phi_p * rho, injected as a cosine lobe along its
// normal into the cell half a cell in front of its surface. Integer atomics on fixed-point values
// (2^24 per watt) make the sum exact and independent of the order the threads add in.
layout(local_size_x = 64) in;

#include "gi/lpv_grid.glsl"
#include "gi/radiosity_trace.glsl"
#include "common/hash.glsl"
#include "common/sampling.glsl"

layout(std430) buffer Inject { int v[]; } inject;

// 2^24 per watt: a VPL carries ~8e-5 W (1380 units; 2^20 gave ~100.5 units, always rounded up to
// 101: +0.4% on the total), and a cell holding every VPL would still fit an int (9e7 < 2^31).
const float LPV_FIXED = 16777216.0;

void add(int cell, int slot, vec3 value) {
    ivec3 q = ivec3(round(value * LPV_FIXED));
    atomicAdd(inject.v[(cell * 4 + slot) * 3 + 0], q.r);
    atomicAdd(inject.v[(cell * 4 + slot) * 3 + 1], q.g);
    atomicAdd(inject.v[(cell * 4 + slot) * 3 + 2], q.b);
}

void main() {
    int p = int(gl_GlobalInvocationID.x);
    const int side = 256, count = side * side;
    if (p >= count) return;
    int walls = params.closed ? RAD_WALLS : CORNELL_WALLS;
    vec3 h = hash_pcg3(vec3(p, 3, 41));
    float cos_t = mix(CORNELL_CONE_OUTER, 1.0, (float(p % side) + h.x) / float(side));
    float phi = 6.28318530718 * (float(p / side) + h.y) / float(side);
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    vec3 w = basis_from_normal(CORNELL_LIGHT_DIR) * vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
    vec3 flux = params.light * cornell_light_intensity(w) * (6.28318530718 * (1.0 - CORNELL_CONE_OUTER)) / float(count);
    RadHit hit = radiosity_trace(CORNELL_LIGHT_POS, w, walls);
    if (!hit.found || hit.back) return;
    RadSurface s = radiosity_surface(hit.surface);
    vec3 n = radiosity_world_normal(s);
    vec3 albedo = params.closed ? vec3(params.rho) : cornell_albedo(s.mesh, s.instance);
    vec3 x = CORNELL_LIGHT_POS + hit.t * w + n * (0.5 * LPV_CELL);
    int cell = lpv_index(lpv_cell_of(x));
    vec3 reflected = flux * albedo;
    add(cell, 0, reflected);
    add(cell, 1, reflected * LPV_LOBE * n.x);
    add(cell, 2, reflected * LPV_LOBE * n.y);
    add(cell, 3, reflected * LPV_LOBE * n.z);
}
