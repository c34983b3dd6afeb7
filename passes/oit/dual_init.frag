#version 450
// Dual depth peeling, initialisation (Bavoil & Myers 2008; 000_c9f7e5de708ecbb3.txt L4189-4199:
// "Keep track of min/max depth in two textures"): every transparent fragment in front of the
// opaque scene writes (1 - z, z) to an RG32F target with MAX blending, so the target holds
// (1 - nearest z, farthest z): the range the first peel starts from. 1 - z instead of the usual
// -z keeps both channels >= 0, so a target cleared to 0 is "no fragment" (near 1 > far 0).
layout(early_fragment_tests) in;
layout(location = 0) out vec4 minmax;
void main() { minmax = vec4(1.0 - gl_FragCoord.z, gl_FragCoord.z, 0.0, 0.0); }
