// Virtual point lights of the Cornell box (instant radiosity, Keller 1997;
// 000_c9f7e5de708ecbb3.txt L5149-5225): the buffer `vpls` holds VPL_SLOTS records, slot
// s = bounce * paths + path, and each VPL has a paraboloid shadow map, layer s of `vpl_maps`
// (d32, 2d-array), over the hemisphere its normal faces. Shared by the generator
// (vpl_generate.comp), the maps' vertex shaders and the gather.
#ifndef PASSLAB_GI_VPL_GLSL
#define PASSLAB_GI_VPL_GLSL
#include "gi/cornell.glsl"

const int VPL_SLOTS = 1024;     // layers of vpl_maps: at most this many VPLs (paths x bounces)
const float VPL_FAR = 3.5;      // map depth = distance / VPL_FAR; the box's diagonal is 2 sqrt 3 = 3.46

struct Vpl {
    vec4 position;  // xyz; w = 1 for a live VPL, 0 for an empty slot (a path that ended)
    vec4 normal;    // xyz
    vec4 flux;      // rgb: the flux the VPL reflects, Phi (radiance Phi/pi cos theta into its hemisphere)
};
layout(std430) buffer Vpls { Vpl vpl[]; } vpls;

// Slots in use and the window of shadow maps (re)built this frame, written by vpl_args.comp.
layout(std430) buffer VplArgs {
    uint surfaces[5];  // VkDrawIndexedIndirectCommand of the maps' draw (vpl_map.vert)
    uint pad_[5];
    uint clears[4];    // VkDrawIndirectCommand of the per-layer depth clear (byte offset 40)
    uint base;        // first slot of this frame's window (slots base .. base + count - 1, mod slots)
    uint slots;       // VPL slots in use: paths * bounces, at most VPL_SLOTS
} vpl_args;

const int VPL_SURFACES = CORNELL_WALLS + 6 * CORNELL_BLOCKS;

// The box's 17 surfaces (5 walls, 6 faces of each block) as instances of the `plane` mesh of
// size 2, for the VPL maps (vpl_map.vert).
// world_from_object of surface k for the `plane` of size 2 ([-1,1]^2, normal +Y): a wall, or face
// f = 0..5 of a block (+X, -X, +Y, -Y, +Z, -Z): the plane halved onto the unit cube's face.
mat4 vpl_surface(int k) {
    if (k < CORNELL_WALLS) return cornell_wall(k);
    int f = (k - CORNELL_WALLS) % 6;
    const float q = 1.5707963;
    mat4 face = f == 0 ? cornell_rot_z(-q) : f == 1 ? cornell_rot_z(q) : f == 2 ? mat4(1.0)
              : f == 3 ? cornell_rot_x(2.0 * q) : f == 4 ? cornell_rot_x(q) : cornell_rot_x(-q);
    return cornell_block((k - CORNELL_WALLS) / 6) * face * cornell_translate(vec3(0.0, 0.5, 0.0)) * cornell_scale(vec3(0.5));
}

// A right-handed frame (t, b, n) about unit n.
mat3 vpl_frame(vec3 n) {
    vec3 t = normalize(abs(n.x) > 0.5 ? cross(n, vec3(0, 1, 0)) : cross(n, vec3(1, 0, 0)));
    return mat3(t, cross(n, t), n);
}

// The paraboloid map of a VPL at y with normal n (000 L5234: "parabolic shadow map"): a unit
// direction u of the hemisphere, in the VPL's frame (u.z >= 0), goes to (s, t) = u.xy / (1 + u.z)
// in the unit disc. Returns (s, t, depth = |p - y| / VPL_FAR, u.z).
vec4 vpl_paraboloid(vec3 p, vec3 y, vec3 n) {
    vec3 r = transpose(vpl_frame(n)) * (p - y);
    float len = length(r);
    vec3 u = r / max(len, 1e-6);
    return vec4(u.xy / max(1.0 + u.z, 1e-3), len / VPL_FAR, u.z);
}
#endif
