// Static LOD selection by the object's size in the image (000_c9f7e5de708ecbb3.txt L5895-5898),
// with a geomorph band before each switch (L5927-5940: hard switching pops, geomorphing
// "interpolates triangle shapes from 1st to 2nd LOD" and needs a geometric correspondence,
// which the QEM collapse sequence gives: host/scene/simplify, docs/format.md "Geomorphs").
//
//   size_px = radius |proj[1][1]| h/2 / z_view            projected radius in pixels
//   l       = log2(detail_px / (c * size_px))              0 while the object is >= detail_px;
//                                                          c is the reactive factor of L5901-5905
//   level   = clamp(floor(l), 0, levels - 1)
//   f       = clamp((fract(l) - (1 - band)) / band, 0, 1)  the last `band` of each level morphs
//                                                          towards the next (0 on the last level)
// At the switch l = k + 1, level k at f = 1 and level k + 1 at f = 0 are the same mesh, so the
// image is continuous: no pop.
#ifndef PASSLAB_LOD_SELECT_GLSL
#define PASSLAB_LOD_SELECT_GLSL
struct PlLod { int level; float morph; float l; };

PlLod pl_lod_select(vec3 centre, float radius, float detail_px, float c, float band, int levels) {
    float z_view = max(-(frame.view * vec4(centre, 1.0)).z, 1e-4);
    // abs: the projection flips y, so proj[1][1] is negative (docs/format.md, [view]).
    float size_px = radius * abs(frame.proj[1][1]) * 0.5 * frame.resolution.y / z_view;
    float l = max(log2(detail_px / (c * size_px)), 0.0);
    PlLod r;
    r.l = l;
    r.level = min(int(floor(l)), levels - 1);
    r.morph = r.level == levels - 1 ? 0.0 : clamp((fract(l) - (1.0 - band)) / band, 0.0, 1.0);
    return r;
}
#endif
