#version 450
// Error against the coverage-weighted reference (passes/aa/post_scene.glsl), for the tests and
// the `error` view, in fp32:
//   x = |aliased - reference|,  y = |MLAA - reference|   (largest channel)
//   z = y - x / 2   (mean(z) <= 0  <=>  MLAA removes at least half of the mean error)
//   w = |MLAA - aliased|          (what MLAA changed)
layout(location = 0) out vec4 errors;
uniform sampler2D color;
uniform sampler2D reference;
uniform sampler2D result;
float maxc(vec3 v) { return max(v.x, max(v.y, v.z)); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(color, p, 0).rgb, r = texelFetch(reference, p, 0).rgb, m = texelFetch(result, p, 0).rgb;
    float e_alias = maxc(abs(c - r)), e_mlaa = maxc(abs(m - r));
    errors = vec4(e_alias, e_mlaa, e_mlaa - 0.5 * e_alias, maxc(abs(m - c)));
}
