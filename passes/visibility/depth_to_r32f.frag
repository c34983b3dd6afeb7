#version 450
// Level 0 of a depth pyramid: the depth attachment copied texel for texel into a colour image
// that has a mip chain (a depth image cannot be a colour target of the max reduction).
layout(location = 0) out float z;
uniform sampler2D depth;
void main() { z = texelFetch(depth, ivec2(gl_FragCoord.xy), 0).r; }
