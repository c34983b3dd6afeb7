// Mistake: the k x k depths are averaged and compared once (000 L4672: "normal bilinear
// filtering cannot be used on depth").
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;

float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    float texel = shadow_texel_world(cameras.light, p, float(textureSize(shadow, 0).y));
    float b = shadow_bias_world(texel, dot(n, l), params.bias_constant, params.bias_slope);
    vec3 coord = shadow_project(cameras.light.view_proj, p + b * l);
    int k = params.kernel;
    ivec2 size = textureSize(shadow, 0);
    ivec2 first = ivec2(floor(coord.xy * vec2(size) - 0.5 * float(k - 1)));
    float depth = 0.0;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) depth += texelFetch(shadow, clamp(first + ivec2(i, j), ivec2(0), size - 1), 0).r;
    return coord.z <= depth / float(k * k) ? 1.0 : 0.0;
}
