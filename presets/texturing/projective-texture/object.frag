#version 450
// Lambert under a dim ambient light plus the slide projector (projector.glsl).
// Second target: the projected light received by points geometrically BEHIND the projector
// (dot(p - eye, forward) <= 0, decided without the projector matrix). It must be exactly 0.
#include "projector.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 behind;
uniform sampler2D slide_uv_grid;
uniform sampler2D slide_checker;
void main() {
    vec3 n = normalize(v_normal);
    vec3 albedo = ALBEDO;
    vec3 light = params.slide == SLIDE_CHECKER ? projector_light(slide_checker, v_world, n)
                                               : projector_light(slide_uv_grid, v_world, n);
    hdr = vec4(albedo * (params.ambient + light), 1.0);
    vec3 forward = normalize(params.proj_target - params.proj_pos);
    behind = vec4(dot(v_world - params.proj_pos, forward) <= 0.0 ? light : vec3(0.0), 1.0);
}
