#version 450
// x_out = x_in + 1: with the group's swap pair, iteration g reads what iteration g-1 wrote.
layout(location = 0) out vec4 x_out;
uniform sampler2D x_in;
void main() { x_out = texelFetch(x_in, ivec2(gl_FragCoord.xy), 0) + 1.0; }
