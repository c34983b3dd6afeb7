#version 450
// Precomputed ambient occlusion, one texel of the atlas per invocation (bake = true: runs once,
// and again only when a param changes). 000_c9f7e5de708ecbb3.txt L4874-4884:
//   "cast n rays into the half sphere oriented by the normal, count blocked rays m,
//    mean visibility V_AO = 1 - m/n; account for Lambert's law: apply cosine distribution
//    around the normal vector; ... ordinary raycasting with maximal distance".
// With cosine-distributed directions the count estimates 004_9a40ad89bdfc582a.txt L692,
//   A(x) / (rho L_i) = integral over the hemisphere of v(x, w) (n . w) dw,   V = A / (rho L_i pi),
// so an open hemisphere gives exactly V = 1. `distribution = uniform` is the count before
// "account for Lambert's law": the unweighted visible solid-angle fraction.
// The bent normal (000 L4865) is the mean of the unblocked directions, normalised.
// The n = rays x rays directions are a stratified grid (passes/common/sampling.glsl), turned
// about the normal by a per-texel hashed angle so neighbouring texels do not band alike.
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
    mat3 frame_n = basis_from_normal(n);
    float turn = 6.2831853 * hash_pcg(vec3(px, 5.0));
    mat3 spin = mat3(cos(turn), sin(turn), 0.0, -sin(turn), cos(turn), 0.0, 0.0, 0.0, 1.0);
    vec3 origin = p + kNormalOffset * n;
    int blocked = 0;
    vec3 bent = vec3(0.0);
    for (int i = 0; i < params.rays; ++i)
        for (int j = 0; j < params.rays; ++j) {
            vec3 local = params.distribution == DISTRIBUTION_COSINE ? hemisphere_cosine(i, j, params.rays)
                                                                    : hemisphere_uniform(i, j, params.rays);
            vec3 w = frame_n * (spin * local);
            if (scene_occluded(origin, w, params.max_distance)) ++blocked;
            else bent += w;
        }
    float v_ao = float(blocked) / float(params.rays * params.rays);  // the occluded fraction m / n
    ao_map = vec4(v_ao, dot(bent, bent) > 0.0 ? normalize(bent) : n);
}
