#version 450
#include "lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in float v_id;
layout(location = 3) in float v_ao;
layout(location = 0) out vec4 hdr_vertex;
void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, frame.camera_pos.xyz - v_world) < 0.0) discard;  // the eye's side, as gbuffer.frag
    hdr_vertex = vec4(params.show == SHOW_AO ? vec3(v_ao) : rtao_shade(v_ao, n, int(v_id + 0.5)), 1.0);
}
