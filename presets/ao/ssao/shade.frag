#version 450
// "Darken the environment lighting by the occlusion amount" (003 L344): a sky-coloured ambient
// term from above, times AO, plus a weak key light so shapes stay readable
// (passes/ao/ambient_lit.glsl, shared with ao/ssao-disk).
#include "ao/ambient_lit.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
uniform sampler2D normal;
uniform sampler2D ao;
void main() {
    vec4 nw = texture(normal, uv);
    lit = vec4(nw.w == 0.0 ? kAoBackground : ao_ambient_lit(nw.xyz, texture(ao, uv).r), 1.0);
}
