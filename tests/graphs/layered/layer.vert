#version 450
#extension GL_ARB_shader_viewport_layer_array : require
// A fullscreen triangle per instance, sent to layer gl_InstanceIndex with value (i+1)/4.
layout(location = 0) flat out vec4 v_color;
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
    gl_Layer = gl_InstanceIndex;
    v_color = vec4(float(gl_InstanceIndex + 1) / 4.0);
}
