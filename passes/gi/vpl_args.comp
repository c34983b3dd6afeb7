#version 450
// The indirect draw arguments of the VPL shadow maps: which slots are (re)built this frame.
// Full: every slot, each frame. Incremental (000_c9f7e5de708ecbb3.txt L5215-5225: "reuse VPLs
// from previous frames, only a couple of new shadow maps per frame"): a window of per_frame
// slots that advances every frame, the maps outside it kept from earlier frames; on the first
// frame after a change (accum_frame 0) every map is cleared, so the window fills them in
// ceil(slots / per_frame) frames. Instance i of the maps' draw renders surface i % 17 (5 walls,
// 12 block faces) into slot (base + i / 17) % slots (vpl_map.vert).
layout(local_size_x = 1) in;
#include "gi/vpl.glsl"
void main() {
    uint slots = min(uint(params.paths * params.bounces), uint(VPL_SLOTS));
    bool window = params.incremental;
    uint count = window ? min(uint(params.per_frame), slots) : slots;
    uint base = window ? (uint(frame.index) * count) % slots : 0u;
    uint cleared = window && frame.accum_frame == 0 ? slots : count;
    vpl_args.surfaces = uint[5](SURFACE_INDICES, 17u * count, 0u, 0u, 0u);
    vpl_args.clears = uint[4](3u, cleared, 0u, 0u);
    vpl_args.base = base;
    vpl_args.slots = slots;
}
