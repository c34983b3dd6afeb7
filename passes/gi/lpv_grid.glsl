// The light propagation volume of presets/gi/light-propagation-volumes: LPV_N^3 cells over the
// Cornell box [-1, 1]^3, each holding per colour channel a first-order SH "flux lobe"
//   I(w) = (c0 + 3 c1 . w) / (4 pi),   integral of I over the sphere = c0,
// so c0 is the cell's flux (the conservation checks sum it). A cell's record in the buffer `lpv`
// is 4 vec4: (c0.rgb), (c1.x.rgb), (c1.y.rgb), (c1.z.rgb); row n of the buffer is iteration n.
#ifndef PASSLAB_GI_LPV_GRID_GLSL
#define PASSLAB_GI_LPV_GRID_GLSL

#define LPV_N 32
const int LPV_CELLS = LPV_N * LPV_N * LPV_N;
const float LPV_CELL = 2.0 / float(LPV_N);
const int LPV_MAX_ITERATIONS = 16;

int lpv_index(ivec3 c) { return (c.z * LPV_N + c.y) * LPV_N + c.x; }
ivec3 lpv_cell_of(vec3 x) { return clamp(ivec3(floor((x + 1.0) / LPV_CELL)), ivec3(0), ivec3(LPV_N - 1)); }

// The lobe a Lambertian emitter of flux phi facing d leaves in the grid: c0 = phi, c1 = (2/3) phi d
// (the clamped cosine's first-order projection: I = (phi / pi) max(0, d . w)).
const float LPV_LOBE = 2.0 / 3.0;

const ivec3 LPV_DIRS[6] = ivec3[](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1), ivec3(0, 0, -1));

// How a cell's flux c0 leaves through its 6 faces, per channel: weight_k = max(0, 1 + 3 (c1 . d_k) / c0),
// normalised so the 6 shares sum to exactly c0 (the linear terms of opposite faces cancel, so
// unclamped weights already sum to 6; the renormalisation keeps clamped lobes conserving too).
void lpv_face_flux(vec3 c0, vec3 c1x, vec3 c1y, vec3 c1z, out vec3 flux[6]) {
    vec3 w[6];
    vec3 total = vec3(0.0);
    for (int k = 0; k < 6; ++k) {
        vec3 d = vec3(LPV_DIRS[k]);
        vec3 proj = c1x * d.x + c1y * d.y + c1z * d.z;
        w[k] = max(vec3(0.0), c0 + 3.0 * proj);  // c0 * (1 + 3 (c1 . d) / c0), no division
        total += w[k];
    }
    for (int k = 0; k < 6; ++k) flux[k] = total.r + total.g + total.b > 0.0 ? c0 * w[k] / max(total, vec3(1e-30)) : vec3(0.0);
}

#endif
