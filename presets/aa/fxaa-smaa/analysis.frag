#version 450
// Tests and the error view, fp32, largest channel:
//   x = |aliased - reference|, y = |result - reference|, z = y - x (< 0 on average: it helps),
//   w = |result - result two frames ago| (T2x: frames 2 and 4 of a static scene agree).
// errors_each: z for each method's own image whatever the mode (one render tests both):
//   x = |fxaa - reference| - x, y = |smaa - reference| - x (SMAA1x of this frame's samples).
layout(location = 0) out vec4 errors;
layout(location = 1) out vec4 errors_each;
uniform sampler2D reference;
uniform sampler2D unjittered;
uniform sampler2D result;
uniform sampler2D result_old_prev;
uniform sampler2D fxaa;
uniform sampler2D smaa;
float maxc(vec3 v) { return max(v.x, max(v.y, v.z)); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 r = texelFetch(reference, p, 0).rgb, a = texelFetch(unjittered, p, 0).rgb, m = texelFetch(result, p, 0).rgb;
    float e_alias = maxc(abs(a - r)), e = maxc(abs(m - r));
    errors = vec4(e_alias, e, e - e_alias, maxc(abs(m - texelFetch(result_old_prev, p, 0).rgb)));
    errors_each = vec4(maxc(abs(texelFetch(fxaa, p, 0).rgb - r)) - e_alias,
                       maxc(abs(texelFetch(smaa, p, 0).rgb - r)) - e_alias, 0.0, 0.0);
}
