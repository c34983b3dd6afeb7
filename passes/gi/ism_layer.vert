#version 450
#extension GL_ARB_shader_viewport_layer_array : require
// One full-screen triangle per VPL slot (instance s -> gl_Layer = s), for the per-level passes of
// the pull-push (ism_push.frag, ism_pull.frag), which also need the layer in the fragment stage.
#include "gi/vpl.glsl"
layout(location = 0) flat out int v_layer;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    gl_Layer = gl_InstanceIndex;
    v_layer = gl_InstanceIndex;
}
