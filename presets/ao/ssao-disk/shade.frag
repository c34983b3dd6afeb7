#version 450
// The ambient term darkened by the visibility (004 L719: "use in the lighting model as a
// factor"), plus a weak key light so shapes stay readable (passes/ao/ambient_lit.glsl, shared
// with ao/ssao). show = ao: the visibility alone.
#include "ao/ambient_lit.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lit;
uniform sampler2D normal;
uniform sampler2D ao;
void main() {
    vec4 nw = texture(normal, uv);
    float v = texture(ao, uv).r;
    if (params.show == SHOW_AO) lit = vec4(vec3(v), 1.0);
    else lit = vec4(nw.w == 0.0 ? kAoBackground : ao_ambient_lit(nw.xyz, v), 1.0);
}
