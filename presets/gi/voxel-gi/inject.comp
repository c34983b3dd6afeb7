#version 450
// Light injection: every voxel the surface marked emits what its surface reflects of the spot,
// L = (rho / pi) E_direct (Lambert), visibility by marching the voxel grid towards the light.
// Every cell, marked or not, also stores that visibility from its centre in `shadow`, which the
// shading samples trilinearly (a 128-step march per pixel cost 167 ms a frame on lavapipe).
// Stored premultiplied with opacity 1 (empty cells: 0, 0), so averaging into coarser levels
// (downsample.comp) gives the mean radiance and coverage a cone sees.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "gi/voxel_scene.glsl"
#include "gi/voxel_cone.glsl"

layout(rgba16f) writeonly uniform image3D radiance_out;
layout(r16f) writeonly uniform image3D shadow_out;

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, ivec3(VX_N)))) return;
    uint id = imageLoad(voxels, c).r;
    vec3 centre = voxel_lo(c) + 0.5 * VX_SIZE;
    imageStore(shadow_out, c, vec4(id != 0u ? 0.0 : voxel_visible(centre, CORNELL_LIGHT_POS)));
    if (id == 0u) {
        imageStore(radiance_out, c, vec4(0.0));
        return;
    }
    int inst = int(id - 1u) / 8, face = int(id - 1u) % 8;
    vec3 albedo = inst < CORNELL_WALLS ? cornell_albedo(0, inst) : cornell_albedo(1, inst - CORNELL_WALLS);
    // The voxel's normal: the dominant axis of its surface's (axis-aligned for walls; the blocks,
    // turned by 17-18 degrees, get the nearest axis: what a one-id voxel can remember).
    vec3 n = voxel_face_normal(face);
    vec3 x = voxel_lo(c) + 0.5 * VX_SIZE;
    float v = voxel_visible(x + n * 1.5 * VX_SIZE, CORNELL_LIGHT_POS);
    vec3 l = params.light * albedo / 3.14159265 * cornell_light_irradiance(x, n) * v;
    imageStore(radiance_out, c, vec4(l, 1.0));
}
