#version 450
// (front-facing, distance from the camera): the near side is front-facing and 2 away.
layout(location = 0) in vec3 world;
layout(location = 0) out vec4 color;
void main() { color = vec4(gl_FrontFacing ? 1.0 : 0.5, length(world - frame.camera_pos.xyz), 0.0, 1.0); }
