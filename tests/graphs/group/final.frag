#version 450
layout(location = 0) out vec4 color;
uniform sampler2D y;
void main() { color = texelFetch(y, ivec2(gl_FragCoord.xy), 0); }
