#version 450
#extension GL_ARB_shader_viewport_layer_array : require
// Clears the depth of the VPL maps being rebuilt: one full-screen triangle at depth 1 per slot of
// the window (instance i -> slot (base + i) % slots), drawn with depth test "always", so the
// other layers keep their maps (an attachment clear would clear every layer).
#include "gi/vpl.glsl"
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
    gl_Layer = int((vpl_args.base + uint(gl_InstanceIndex)) % vpl_args.slots);
}
