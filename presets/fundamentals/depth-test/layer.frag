#version 450
// Colour by depth rank (so the image does not depend on the order) and count the fragment.
// The counting is a side effect, which would normally disable early depth testing (the shader
// could have to run even for a fragment that fails): early_fragment_tests forces the test
// before the shader, as early-z does for side-effect-free shaders (000 L6045-6047).
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
