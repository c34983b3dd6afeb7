#version 450
// A surfel's splat (000 L5248-5253, "imperfect: smaller points"): the texel's direction u (the
// inverse paraboloid of its centre (s, t), u = (2s, 2t, 1 - s^2 - t^2) / (1 + s^2 + t^2),
// gi/vpl.glsl's map inverted) hits the disc's
// plane n . (x - c) = 0 at x = lambda u, lambda = (n . c) / (n . u); the texel is kept if x lies
// within R of the centre c, with the depth lambda / VPL_FAR: the surface's own depth there, not
// the centre's (a floor seen at a grazing angle spans many depths over one splat). Written to
// level 0 of the pull-push pyramid `ism_push` (r32f) behind the depth test on `ism_depth`; the
// clear 1.0 marks a texel no splat covered: a hole.
#include "gi/vpl.glsl"
layout(location = 0) flat in vec4 v_centre;
layout(location = 1) flat in vec3 v_normal;
layout(location = 0) out vec4 o_depth;
void main() {
    // TODO: the surfel's depth at this texel (000 L5240-5253). The texel's centre in the map is
    //     (s, t) = (2 x / w - 1, 1 - 2 y / h)   (gl_FragCoord.xy, frame.target = (w, h, 1/w, 1/h);
    //                                           ism_splat.vert draws (s, -t)),
    // its direction from the VPL (the paraboloid inverted) u = (2s, 2t, 1 - s^2 - t^2) / (1 + s^2 + t^2),
    // and the ray lambda u meets the disc's plane n . (x - c) = 0 (c = v_centre.xyz, n = v_normal,
    // both in the VPL's frame) at lambda = (n . c) / (n . u). Keep the texel (else discard) only
    // inside the paraboloid's disc (s^2 + t^2 < 1), in front (lambda > 0) and within R = v_centre.w of c;
    // its depth is lambda / VPL_FAR. As shipped: the centre's depth over the whole square sprite.
    float depth = length(v_centre.xyz) / VPL_FAR;
    gl_FragDepth = depth;
    o_depth = vec4(depth, 0.0, 0.0, 0.0);
}
