#version 450
// EXERCISE — this file shadows the preset's layer.frag (TODO 3; TODO 1-2 are in layer.vert).
// Colour by depth rank (so the image does not depend on the order) and count the fragment.
// TODO 3: sorted front to back, early-z rejects hidden fragments before they are shaded
// (000 L6045-6047). But this shader has a side effect, the counter: by default the depth test
// then runs after the shader (the shader could have to run even for a fragment that fails),
// and every fragment would be counted. Declare that the per-fragment tests run before this
// shader, so a fragment that fails the depth test is neither shaded nor counted.
layout(early_fragment_tests) in;
layout(location = 0) flat in int v_rank;
layout(location = 0) out vec4 color;
layout(std430) buffer fragments { uint shaded; };
layout(r32ui) uniform uimage2D overdraw;
void main() {
    atomicAdd(shaded, 1u);
    imageAtomicAdd(overdraw, ivec2(gl_FragCoord.xy), 1u);
    float t = float(v_rank) / float(max(params.layers - 1, 1));
    color = vec4(mix(vec3(1.0, 0.55, 0.2), vec3(0.2, 0.35, 0.9), t), 1.0);
}
