#version 450
// Test-only reference: the same rectangle tested against every level-0 depth texel it covers
// (no pyramid, and its own loop: nothing of hiz.glsl but the rectangle). hidden[i] = 1 when the box is behind all of them. The pyramid test is
// conservative: it may keep a hidden box (its 2x2 texels reach beyond the rectangle), but it
// must never cull a box this test keeps.
layout(local_size_x = 64) in;
#include "visibility/scene.glsl"
#include "visibility/hiz.glsl"
uniform sampler2D depth0;   // level 0 alone
layout(std430) readonly buffer CullStats { uint culled; uint tested; uint level[16]; int object_level[]; } stats;
// count: boxes hidden by this test; violations: boxes the pyramid culled that this test keeps.
layout(std430) buffer Hidden { uint count; uint violations; uint hidden[]; } brute;
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= PL_VIS_OBJECTS) return;
    PlBox b = pl_vis_object(i);
    PlScreenRect r = pl_screen_rect(b.centre, b.half_size, frame.view_proj, vec2(textureSize(depth0, 0)));
    float m = 0.0;
    for (int y = r.lo.y; y <= r.hi.y; ++y)
        for (int x = r.lo.x; x <= r.hi.x; ++x) m = max(m, texelFetch(depth0, ivec2(x, y), 0).r);
    bool h = r.ok && r.zmin > m;
    brute.hidden[i] = h ? 1u : 0u;
    if (h) atomicAdd(brute.count, 1u);
    if (stats.object_level[i] >= 0 && !h) atomicAdd(brute.violations, 1u);
}
