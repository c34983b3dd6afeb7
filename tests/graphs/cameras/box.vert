#version 450
// The unit box moved to (2, 0, -1), seen through the pass camera's frame block.
layout(location = 0) in vec3 position;
void main() { gl_Position = frame.view_proj * vec4(position + vec3(2.0, 0.0, -1.0), 1.0); }
