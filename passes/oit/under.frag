#version 450
// Composite one peeled layer under the accumulator, front to back ("Compose n layers",
// 000_c9f7e5de708ecbb3.txt L4181): the pass's blend { one_minus_dst_alpha, one } adds
// (a * rgb, a) * (1 - acc.a), oit_under of composite.glsl. An empty pixel of the layer is (0,0,0,0).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 acc;
uniform sampler2D layer;
void main() {
    vec4 c = texelFetch(layer, ivec2(gl_FragCoord.xy), 0);
    // premultiply: the blend state multiplies the whole source by (1 - acc.a)
    acc = vec4(c.rgb * c.a, c.a);
}
