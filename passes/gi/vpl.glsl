// Virtual point lights of the Cornell box (instant radiosity, Keller 1997;
// 000_c9f7e5de708ecbb3.txt L5149-5225): the buffer `vpls` holds VPL_SLOTS records, slot
// s = bounce * paths + path, and each VPL has a paraboloid shadow map, layer s of `vpl_maps`
// (d32, 2d-array), over the hemisphere its normal faces. Shared by the generator
// (vpl_generate.comp), the maps' vertex shaders and the gather.
#ifndef PASSLAB_GI_VPL_GLSL
#define PASSLAB_GI_VPL_GLSL

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
