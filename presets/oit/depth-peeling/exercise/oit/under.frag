#version 450
// EXERCISE — this file shadows the shared oit/under.frag for oit/depth-peeling only.
//     passlab run   presets/oit/depth-peeling --exercise presets/oit/depth-peeling/exercise
//     passlab grade presets/oit/depth-peeling --exercise presets/oit/depth-peeling/exercise
// Composite one peeled layer under the accumulator, front to back ("Compose n layers",
// 000_c9f7e5de708ecbb3.txt L4181): the pass's blend { one_minus_dst_alpha, one } adds
// (a * rgb, a) * (1 - acc.a), oit_under of composite.glsl. An empty pixel of the layer is (0,0,0,0).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 acc;
uniform sampler2D layer;
void main() {
    vec4 c = texelFetch(layer, ivec2(gl_FragCoord.xy), 0);
    // TODO (under): premultiply: the blend state multiplies the whole source by (1 - acc.a)
    //   acc = (rgb * a, a)    (the blend adds it times 1 - acc.a: oit_under of composite.glsl)
    acc = vec4(0.0);
}
