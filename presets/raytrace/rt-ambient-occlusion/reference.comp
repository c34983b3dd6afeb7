#version 450
// Test-only: presets/ao/precomputed-ao's visibility at the same points, computed by its own
// scene (passes/ao/scene.glsl: the analytic solids of scene "objects") with the bake's 1024
// feelers: the same cosine grid, the same per-point turn (bake.frag's hashed angle), the
// same normal offset and feeler length. No BVH, no triangles: what the rays must reproduce.
layout(local_size_x = 8, local_size_y = 8) in;
// precomputed-ao's scene.glsl reads its `scene` param; here it is always "objects", the scene
// make_scene.py triangulated.
struct PrecomputedAoParams { int scene; };
const PrecomputedAoParams kObjects = PrecomputedAoParams(0);
#define SCENE_OBJECTS 0
#define SCENE_SPHERE 1
#define SCENE_BOX 2
#define SCENE_BOWL 3
#define SCENE_CREASE 4
#define params kObjects
#include "ao/scene.glsl"
#undef params
#include "raytrace/rtao.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(r32f) writeonly uniform image2D ao_ref;
layout(r8) writeonly uniform image2D compared;  // 1: a vertex on the visible surface

// Floor vertices under the box (and on its rim) lie inside precomputed-ao's *solid* box, which
// blocks every feeler (V = 0), while the mesh's box is a shell the feelers cross from inside.
// No view ever shades them (the box covers them), so they are left out of the comparison.
bool hidden_in_box(vec3 p, int id) {
    return id == 0 && all(lessThanEqual(abs(p.xz - kBoxCentre.xz), kBoxHalf.xz + 1e-3));
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(ao_ref)))) return;
    vec4 pos = texelFetch(g_position, p, 0);
    float v = 1.0;
    vec4 gn = texelFetch(g_normal, p, 0);
    imageStore(compared, p, vec4(pos.w > 0.0 && !hidden_in_box(pos.xyz, int(gn.w + 0.5)) ? 1.0 : 0.0));
    if (pos.w > 0.0) {
        vec3 n = normalize(gn.xyz);
        // bake.frag's turn of the grid about n, written out here rather than shared with rtao.glsl.
        float turn = 6.2831853 * hash_pcg(vec3(p, 5.0));
        mat3 frame_n = basis_from_normal(n), spin = mat3(cos(turn), sin(turn), 0.0, -sin(turn), cos(turn), 0.0, 0.0, 0.0, 1.0);
        vec3 origin = pos.xyz + kRtaoNormalOffset * n;
        int blocked = 0;
        for (int i = 0; i < params.rays; ++i)
            for (int j = 0; j < params.rays; ++j)
                if (scene_occluded(origin, frame_n * (spin * hemisphere_cosine(i, j, params.rays)), params.max_distance)) ++blocked;
        v = 1.0 - float(blocked) / float(params.rays * params.rays);  // V_AO = 1 - m / n (000 L4879)
    }
    imageStore(ao_ref, p, vec4(v));
}
