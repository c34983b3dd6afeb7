#version 450
// One thread per object: project its box (pl_screen_rect), test it against the max-Z pyramid of
// the occluders at the level where its rectangle spans 2x2 texels (visibility/hiz.glsl,
// 000_c9f7e5de708ecbb3.txt L6292-6301), and append the survivors to the visible list, whose
// count is the indirect draw's instance count. The GPU also counts what it culled and how
// often each level was used, for the preset's figures.
layout(local_size_x = 64) in;
#include "visibility/scene.glsl"
#include "visibility/hiz.glsl"
uniform sampler2D hiz;
layout(std430) buffer Visible { uint id[]; } visible;
layout(std430) buffer DrawArgs { uint vertex_count; uint instance_count; uint first_vertex; uint first_instance; } draw_args;
// culled: objects rejected; level[k]: objects tested at level k; per object: its level, or -1.
layout(std430) buffer CullStats { uint culled; uint tested; uint level[16]; int object_level[]; } stats;
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i == 0) draw_args.vertex_count = 36u;   // the buffer is cleared to 0 every frame
    if (i >= PL_VIS_OBJECTS) return;
    PlBox b = pl_vis_object(i);
    PlScreenRect r = pl_screen_rect(b.centre, b.half_size, frame.view_proj, vec2(textureSize(hiz, 0)));
    int k = pl_hiz_level(r, textureQueryLevels(hiz), params.refine);
    atomicAdd(stats.tested, 1u);
    atomicAdd(stats.level[k], 1u);
    if (pl_hiz_occluded(hiz, r, k)) {
        atomicAdd(stats.culled, 1u);
        stats.object_level[i] = k;
        return;
    }
    stats.object_level[i] = -1;
    visible.id[atomicAdd(draw_args.instance_count, 1u)] = uint(i);
}
