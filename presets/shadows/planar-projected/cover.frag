#version 450
// Test-only mask: 1 where a flat caster copy lands on the receiver (stencil == 1 from the ground
// pass, tested, never written), whatever the method draws afterwards: the pixels where the
// shadow must be exactly 1 - opacity.
layout(location = 0) out vec4 cover;
void main() { cover = vec4(1.0); }
