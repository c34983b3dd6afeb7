#version 450
layout(location = 0) out float z;
uniform sampler2D depth;
void main() { z = texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r; }
