// The photon map of presets/gi/photon-mapping: photon records and the uniform grid that replaces
// the course's kd-tree (000_c9f7e5de708ecbb3.txt L5094: "requires fast spatial search (kd-tree)").
//
// Photon p's bounce b (b = 0: where it first lands) is record p * PM_BOUNCES + b of the buffer
// `photons`: { vec4 position_flux_r; vec4 normal_flux_g; vec4 incoming_flux_b; } (48 bytes; an
// absent bounce has flux 0). The grid covers the box [-1, 1]^3 with PM_GRID^3 cells; after a
// counting sort, the records in cell c are sorted[start[c] .. start[c + 1] - 1].
#ifndef PASSLAB_GI_PHOTON_MAP_GLSL
#define PASSLAB_GI_PHOTON_MAP_GLSL

#ifndef PM_PHOTONS
#define PM_PHOTONS 65536
#endif
#ifndef PM_BOUNCES
#define PM_BOUNCES 4
#endif
#define PM_GRID 32
const int PM_RECORDS = PM_PHOTONS * PM_BOUNCES;
const int PM_CELLS = PM_GRID * PM_GRID * PM_GRID;
const float PM_CELL = 2.0 / float(PM_GRID);

struct Photon {
    vec3 position;
    vec3 normal;    // of the surface it landed on (the gather ignores photons of other sides)
    vec3 incoming;  // direction it travelled
    vec3 flux;      // watts per channel
};

ivec3 photon_cell_coords(vec3 x) { return clamp(ivec3(floor((x + 1.0) / PM_CELL)), ivec3(0), ivec3(PM_GRID - 1)); }
int photon_cell_index(ivec3 c) { return (c.z * PM_GRID + c.y) * PM_GRID + c.x; }

#endif
