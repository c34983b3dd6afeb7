#version 450
// The shared OIT scene, one quad per instance (quad_vertex.glsl).
#include "oit/quad_vertex.glsl"
void main() { oit_emit_quad(gl_InstanceIndex); }
