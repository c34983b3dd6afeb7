// Shared OIT scene geometry (scene.glsl): oit_emit_quad(q) places this vertex of quad q, six
// vertices per quad (or per cell, below). quads.vert draws quad gl_InstanceIndex, so the
// transparent quads are one instanced draw (OIT_INSTANCES = 32 instances) that
// `order_independent` can submit in any order; a sorted draw picks q from its own order buffer.
// OPAQUE = 1 draws the opaque occluder instead (absent in the full-screen stack case).
// OIT_TESS = g (default 1) cuts every quad into a g x g grid of cells, 6 vertices each
// (vertex_count = 6*g*g): the heavy case, g = 40 gives 32 * 3200 = 102400 transparent triangles
// that cover exactly the same pixels at the same depths, so every reference still applies.
#include "oit/scene.glsl"
#ifndef OIT_TESS
#define OIT_TESS 1
#endif
layout(location = 0) flat out vec4 v_color;

void oit_emit_quad(int q) {
    const ivec2 corner[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
    int cell = gl_VertexIndex / 6;
    vec2 t = (vec2(cell % OIT_TESS, cell / OIT_TESS) + vec2(corner[gl_VertexIndex % 6])) / float(OIT_TESS);
#if OPAQUE
    vec4 r = params.stack > 0 ? vec4(2.0) : kOitOpaqueRect;
    vec2 p = mix(r.xy, r.zw, t);
    gl_Position = vec4(p, kOitOpaqueDepth, 1.0);
    v_color = vec4(kOitOpaqueRgb, 1.0);
#else
    OitQuad k = oit_quad(q, params.stack);
    vec2 p = mix(k.rect.xy, k.rect.zw, t);
    gl_Position = vec4(p, oit_depth(k, p), 1.0);
    v_color = vec4(k.rgb, params.alpha);
#endif
}
