#version 450
// A pass without a camera: frame.target is its render area, frame.resolution stays the view's.
layout(location = 0) out vec4 color;
void main() { color = vec4(frame.target.xy, frame.resolution.xy); }
