#version 450
// LOD level LEVEL of the chain, drawn for every teapot whose selection is this level (the others
// are moved outside the clip volume: zero-area, no fragments). Levels 0 and 1 have morph targets
// into the next level (locations 4..6) and geomorph in their last `band`; the last level and the
// references (PLAIN and REFERENCE: every teapot at LEVEL, unmorphed) have none. `params.morph >= 0` forces every teapot to
// level 0 with that factor
// (the tests of the geomorph's ends).
#include "teapots.glsl"
#include "visibility/lod_select.glsl"
#include "visibility/lod_emit.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
#if !PLAIN
layout(location = 4) in vec3 morph_position;
layout(location = 5) in vec3 morph_normal;
layout(location = 6) in vec2 morph_uv;
#endif
layout(location = 3) flat out uint v_triangle_base;
layout(location = 4) out vec3 v_tint;   // LOD colour (params.tint)
void main() {
    int i = gl_InstanceIndex;
    vec3 c = teapot_centre(i);
    // STEP (test-only passes): the same frame a small step later, detail x 1.005 and morph + 0.01.
    PlLod lod = pl_lod_select(c, TEAPOT_RADIUS, params.detail * (STEP != 0 ? 1.005 : 1.0), params.c, params.band, 3);
    float f = lod.morph;
    int level = lod.level;
    if (params.morph >= 0.0) { level = 0; f = min(params.morph + (STEP != 0 ? 0.01 : 0.0), 1.0); }   // forced: LOD 0 by hand
#if REFERENCE
    level = LEVEL; f = 0.0;
#endif
    v_triangle_base = uint((LEVEL * TEAPOTS + i) * 4096);
    v_tint = vec3(LEVEL == 0, LEVEL == 1, LEVEL == 2) * (1.0 - 0.6 * f);
    if (level != LEVEL) { gl_Position = vec4(0.0, 0.0, 2.0, 1.0); return; }
#if PLAIN
    emit(c + position, normal, uv);
#else
    emit(c + pl_geomorph(position, morph_position, f), pl_geomorph(normal, morph_normal, f), pl_geomorph(uv, morph_uv, f));
#endif
}
