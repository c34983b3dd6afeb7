// Ray-traced ambient occlusion over the host BVH (000_c9f7e5de708ecbb3.txt L5781-5785):
//   "Randomly chose directions over hemisphere at a surface point. Like shadows, miss shader
//    tells us if a point is occluded or not. Compute average."
// The AO definition is presets/ao/precomputed-ao's (000 L4874-4884), so the two can be compared:
//   V = 1 - m / n,   n cosine-distributed feelers of length max_distance, m of them blocked,
// which estimates (1/pi) * integral over the hemisphere of v(x, w) (n . w) dw (004 L692): an open
// hemisphere gives V = 1 exactly. The n = grid^2 directions are the same stratified grid as the
// bake's (passes/common/sampling.glsl, hemisphere_cosine), turned about the normal by the same
// per-point hashed angle, so at the same point and normal the two estimators use the same rays.
//
// A frame traces only `count` cells of the grid (a real-time budget: 000 L5789-5793 trace
// 0.25 ray per pixel), cells first .. first + count - 1 (mod grid^2); the caller averages the
// frames. After grid^2 / count frames every cell was traced once and the running mean is the
// full stratified estimate; later sweeps turn the grid by the golden angle, so the mean keeps
// converging instead of repeating the same rays.
//
// The "miss shader" of the seed is a false from pl_bvh_occluded: an any-hit query that stops
// at the first triangle within the feeler (raytrace/bvh.glsl).
#ifndef PASSLAB_RAYTRACE_RTAO_GLSL
#define PASSLAB_RAYTRACE_RTAO_GLSL
#include "raytrace/bvh.glsl"
#include "common/sampling.glsl"
#include "common/hash.glsl"

// Feelers start this far off the surface along n, as in the bake (precomputed-ao bake.frag):
// the surface never blocks itself, and 1e-4 is 3000 times below the scene's smallest feature.
const float kRtaoNormalOffset = 1e-4;

// The per-point rotation of the grid about n for sweep `sweep` (0: the bake's angle).
mat3 rtao_spin(ivec2 key, int sweep) {
    float turn = 6.2831853 * fract(hash_pcg(vec3(key, 5.0)) + 0.6180340 * float(sweep));
    return mat3(cos(turn), sin(turn), 0.0, -sin(turn), cos(turn), 0.0, 0.0, 0.0, 1.0);
}

// Visible fraction over `count` cells of the grid x grid stratification, starting at cell
// `first` (cells past grid^2 wrap into the next sweep), for the point p with unit normal n;
// `key` seeds the rotation (the point's texel). Mesh 0 of the scene buffer, placed at the origin.
float rtao_visibility(vec3 p, vec3 n, ivec2 key, int first, int count, int grid, float max_distance) {
    mat3 frame_n = basis_from_normal(n);
    vec3 origin = p + kRtaoNormalOffset * n;
    int cells = grid * grid, open = 0;
    for (int s = 0; s < count; ++s) {
        int c = first + s, k = c % cells;
        vec3 w = frame_n * (rtao_spin(key, c / cells) * hemisphere_cosine(k / grid, k % grid, grid));
        if (!pl_bvh_occluded(0u, mat4(1.0), origin, w, 0.0, max_distance)) ++open;  // the "miss shader"
    }
    return float(open) / float(count);
}

// Running mean over frames (weight 1 / (frame + 1)): frame 0 starts it afresh.
float rtao_accumulate(float previous, float current, uint frame) {
    return frame == 0u ? current : mix(previous, current, 1.0 / float(frame + 1u));
}
#endif
