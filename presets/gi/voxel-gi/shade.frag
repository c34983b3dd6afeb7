#version 450
// Voxel GI shading: direct light from the spot with the visibility inject.comp marched from every
// cell (sampled trilinearly one cell off the surface: soft, voxel-sized shadow edges), plus one
// indirect bounce gathered by 6 cones over the hemisphere (one along the normal, five at 60
// degrees; weights 0.25 and 0.15 approximating the cosine lobe, summing to 1), so
// L = (rho / pi) E_direct V + rho * sum_k w_k L_cone,k. By default the cones are traced once per
// surface cell (gather.comp) and interpolated here; `per_pixel` traces them for every fragment
// (the passes compiled with VX_PER_PIXEL = 1: a define, since an untaken branch still costs on
// lavapipe).
#define VX_CONES 1
#include "gi/voxel_scene.glsl"
#include "gi/voxel_cone.glsl"


layout(location = 0) in vec3 object_pos;
layout(location = 1) flat in int instance;
layout(location = 2) in vec3 world_pos;
layout(location = 3) in vec3 world_normal;
layout(location = 0) out vec4 color;

uniform sampler3D shadow;
uniform sampler3D indirect_volume;

void main() {
    vec3 x = world_pos, n = normalize(world_normal);
    vec3 albedo = cornell_albedo(MESH, instance);
    float v = textureLod(shadow, voxel_uvw(x + n * VX_SIZE), 0.0).r;
    vec3 direct = params.light * albedo / 3.14159265 * cornell_light_irradiance(x, n) * v;
    vec3 indirect = vec3(0.0);
    if (params.indirect) {
#if VX_PER_PIXEL
        indirect = voxel_hemisphere(x + n * 1.5 * VX_SIZE, n);  // the real thing: 6 cones here
#else
        vec4 g = textureLod(indirect_volume, voxel_uvw(x), 0.0);  // gathered per cell
        indirect = g.rgb / max(g.a, 1e-4);
#endif
        indirect *= albedo;
    }
    color = vec4((direct + indirect) * params.exposure, 1.0);
}
