#version 450
// The indirect arguments of the imperfect-shadow-map passes (every slot, every rebuild):
//   vpl_args.surfaces  the triangle maps' indexed draw (gi/vpl_map.vert, test/diff only),
//   vpl_args.clears    one full-screen triangle per slot (gi/vpl_clear.vert: the per-layer passes
//                      of the pull-push and the triangle maps' clear),
//   ism_args           the splat: points_per_vpl vertices x slots instances (gi/ism_splat.vert).
layout(local_size_x = 1) in;
#include "gi/vpl.glsl"
layout(std430) buffer IsmArgs { uint splat[4]; } ism_args;
void main() {
    uint slots = min(uint(params.paths * params.bounces), uint(VPL_SLOTS));
    vpl_args.surfaces = uint[5](SURFACE_INDICES, 17u * slots, 0u, 0u, 0u);
    vpl_args.clears = uint[4](3u, slots, 0u, 0u);
    vpl_args.base = 0u;
    vpl_args.slots = slots;
    ism_args.splat = uint[4](uint(params.points), slots, 0u, 0u);
}
