#version 450
// The culled render, or the id image in false colour (pl_vis_color per box, grey the wall).
#include "visibility/scene.glsl"
uniform sampler2D scene;
uniform usampler2D ids;
layout(location = 0) out vec4 color;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (params.show == SHOW_SCENE) { color = texelFetch(scene, p, 0); return; }
    uint id = texelFetch(ids, p, 0).r;
    vec3 c = id == 0u ? vec3(0.0) : id > uint(PL_VIS_OBJECTS) ? vec3(0.5) : pl_vis_color(int(id) - 1);
    color = vec4(c, 1.0);
}
