#version 450
// Shared OIT scene geometry (scene.glsl): six vertices per quad, one quad per instance, so the
// transparent quads are one instanced draw that `order_independent` can submit in any order.
// OPAQUE = 1 draws the opaque occluder instead (absent in the full-screen stack case).
#include "oit/scene.glsl"
layout(location = 0) flat out vec4 v_color;

void main() {
    const ivec2 corner[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
    ivec2 c = corner[gl_VertexIndex % 6];
#if OPAQUE
    vec4 r = params.stack > 0 ? vec4(2.0) : kOitOpaqueRect;
    vec2 p = vec2(c.x == 0 ? r.x : r.z, c.y == 0 ? r.y : r.w);
    gl_Position = vec4(p, kOitOpaqueDepth, 1.0);
    v_color = vec4(kOitOpaqueRgb, 1.0);
#else
    OitQuad k = oit_quad(gl_InstanceIndex, params.stack);
    vec2 p = vec2(c.x == 0 ? k.rect.x : k.rect.z, c.y == 0 ? k.rect.y : k.rect.w);
    gl_Position = vec4(p, oit_depth(k, p), 1.0);
    v_color = vec4(k.rgb, params.alpha);
#endif
}
