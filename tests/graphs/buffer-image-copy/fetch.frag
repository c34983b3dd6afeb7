#version 450
// Texel-exact readout: texelFetch, so no filtering or coordinate rounding can hide a decode error.
layout(location = 0) out vec4 color;
uniform sampler2D src;
void main() { color = texelFetch(src, ivec2(gl_FragCoord.xy), 0); }
