#version 450
// Test pass: a constant in-scatter field (0.5, 0.25, 0.125) for the blur's "keeps a constant
// field" check (tile_blur.frag is run on it with the real depth buffer's edges).
layout(location = 0) out vec4 color;
void main() { color = vec4(0.5, 0.25, 0.125, 1.0); }
