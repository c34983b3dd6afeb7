#version 450
// EXERCISE — precomputed ambient occlusion, the bake (000_c9f7e5de708ecbb3.txt L4862-4884,
// 004_9a40ad89bdfc582a.txt L682-715). One invocation per texel of the atlas: the texel's surface
// point p and normal n are given; cast feelers, count the blocked ones, write V_AO and the bent
// normal. Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   ao/precomputed-ao --exercise presets/ao/precomputed-ao/exercise --set show=ao
//     passlab grade ao/precomputed-ao --exercise presets/ao/precomputed-ao/exercise
// The helpers: passes/common/sampling.glsl (hemisphere_uniform(i, j, m), hemisphere_cosine(i, j,
// m): stratified directions in a frame whose +z is the normal; basis_from_normal(n) turns such a
// frame into world space) and passes/ao/scene.glsl (scene_occluded(origin, w, t_max): does a
// feeler from origin along the unit direction w hit a solid within t_max?).
#include "ao/scene.glsl"
#include "common/sampling.glsl"
#include "common/hash.glsl"
layout(location = 0) out vec4 ao_map;  // r: V_AO, gba: bent normal (world)

// Feelers start this far off the surface along n, so the surface never blocks itself; small
// against every feature of the scene (the smallest, the 0.3 ball, is 3000x larger).
const float kNormalOffset = 1e-4;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), tile = px / params.tile;
    int id = tile.y * 4 + tile.x;
    if (id >= kSurfaces || !surface_present(id)) {
        ao_map = vec4(1.0, 0.0, 1.0, 0.0);
        return;
    }
    vec2 uv = (vec2(px - tile * params.tile) + 0.5) / float(params.tile);  // texel centre on the patch
    vec3 p, n;
    surface_point(id, uv, p, n);
    mat3 frame_n = basis_from_normal(n);   // local (x, y, z) -> world, z along n
    float turn = 6.2831853 * hash_pcg(vec3(px, 5.0));
    mat3 spin = mat3(cos(turn), sin(turn), 0.0, -sin(turn), cos(turn), 0.0, 0.0, 0.0, 1.0);
    vec3 origin = p + kNormalOffset * n;
    int blocked = 0;
    vec3 bent = vec3(0.0);
    for (int i = 0; i < params.rays; ++i)
        for (int j = 0; j < params.rays; ++j) {
            // TODO 1: the feeler's direction w (unit, world space) for stratum (i, j): "cast n
            // rays into the half sphere oriented by the normal ... account for Lambert's law:
            // apply cosine distribution around the normal vector" (L4876-4881). With
            // distribution = cosine the directions must be distributed with density cos(theta) / pi
            // about n (then counting them estimates the cosine-weighted integral of 004 L692);
            // with distribution = uniform, uniformly over the hemisphere (the plain count).
            // Turn the local direction by `spin` (about the local +z) before leaving the frame.
            vec3 w = n;

            // TODO 2: "count blocked rays m" (L4877), with "ordinary raycasting with maximal
            // distance" params.max_distance (L4882-4883), and gather what the bent normal needs:
            // it points "into the direction of average visibility" (L4865).

        }
    // TODO 3: the mean visibility V_AO = 1 - m / n (L4878) over the n = rays^2 feelers, and the
    // bent normal, a unit vector (where every feeler is blocked, fall back to n).
    float v_ao = 0.0;
    ao_map = vec4(v_ao, n);
}
