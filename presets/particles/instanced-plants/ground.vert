#version 450
layout(location = 0) in vec3 position;
void main() { gl_Position = frame.view_proj * vec4(position, 1.0); }
