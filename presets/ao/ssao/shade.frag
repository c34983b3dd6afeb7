#version 450
// "Darken the environment lighting by the occlusion amount" (003 L344): a sky-coloured ambient
// term from above, times AO, plus a weak key light so shapes stay readable
// (passes/ao/ambient_lit.glsl, shared with ao/ssao-disk). show = ao / raw: the blurred or the
// raw occlusion instead. One pass writes the display image directly (no lit intermediate).
#include "ao/ambient_lit.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D normal;
uniform sampler2D ao;
uniform sampler2D ao_raw;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);  // every image here has the view's size: texel = pixel
    float a = texelFetch(ao, px, 0).r;
    vec3 c;
    if (params.show == SHOW_AO) c = vec3(a);
    else if (params.show == SHOW_RAW) c = vec3(texelFetch(ao_raw, px, 0).r);
    else {
        vec4 nw = texelFetch(normal, px, 0);
        c = nw.w == 0.0 ? kAoBackground : ao_ambient_lit(nw.xyz, a);
    }
    ldr = vec4(clamp(c, 0.0, 1.0), 1.0);
}
