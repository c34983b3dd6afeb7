#version 450
// MLAA step 3, blending (000_c9f7e5de708ecbb3.txt L3359: "Anti-Aliasing using blending map from
// step 2"). Pixel q gathers the four weights that concern it: from its own record the parts it
// takes across its top and left edges, from its bottom and right neighbours' records the parts
// it takes across theirs:
//   w = (w_top, w_bottom, w_left, w_right),   c_i = mix(c_q, c_neighbour_i, w_i)
//   result = sum_i w_i c_i / sum_i w_i        (= c_q exactly where every w_i = 0)
// With one non-zero weight this is mix(c_q, c_n, w): the pixel becomes its coverage-weighted
// colour. Where several meet (a corner) it averages the one-sided blends, as Jimenez et al.'s
// neighbourhood blending does with its four bilinear lookups; here the mixes are explicit (exact
// weights, no 8-bit bilinear fractions).
// Reads `color` and `weights` (aa/mlaa_weights.frag or the same layout), writes `result`.
layout(location = 0) out vec4 result;
uniform sampler2D color;
uniform sampler2D weights;
void main() {
    ivec2 q = ivec2(gl_FragCoord.xy), last = textureSize(color, 0) - 1;
    ivec2 up = max(q - ivec2(0, 1), 0), down = min(q + ivec2(0, 1), last);
    ivec2 left = max(q - ivec2(1, 0), 0), right = min(q + ivec2(1, 0), last);
    vec4 own = texelFetch(weights, q, 0);
    vec4 w = vec4(own.x, q.y < last.y ? texelFetch(weights, down, 0).y : 0.0,
                  own.z, q.x < last.x ? texelFetch(weights, right, 0).w : 0.0);
    vec4 c = texelFetch(color, q, 0);
    float sum = w.x + w.y + w.z + w.w;
    if (sum <= 0.0) {
        result = c;
        return;
    }
    vec4 acc = w.x * mix(c, texelFetch(color, up, 0), w.x) + w.y * mix(c, texelFetch(color, down, 0), w.y) +
               w.z * mix(c, texelFetch(color, left, 0), w.z) + w.w * mix(c, texelFetch(color, right, 0), w.w);
    result = acc / sum;
}
