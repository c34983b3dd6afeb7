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
    vec2 st = vec2(gl_FragCoord.x * frame.target.z * 2.0 - 1.0, 1.0 - gl_FragCoord.y * frame.target.w * 2.0);  // ism_splat.vert draws (s, -t)
    float q = dot(st, st);
    vec3 u = vec3(2.0 * st, 1.0 - q) / (1.0 + q);
    float nu = dot(v_normal, u);
    float lambda = dot(v_normal, v_centre.xyz) / (abs(nu) > 1e-6 ? nu : 1e-6);
    if (q >= 1.0 || lambda <= 0.0 || distance(lambda * u, v_centre.xyz) > v_centre.w) discard;
    float depth = lambda / VPL_FAR;
    gl_FragDepth = depth;
    o_depth = vec4(depth, 0.0, 0.0, 0.0);
}
