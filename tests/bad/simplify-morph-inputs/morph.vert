#version 450
layout(location = 0) in vec3 position;
layout(location = 4) in vec3 morph_position;
void main() { gl_Position = vec4(mix(position, morph_position, 0.5), 1.0); }
