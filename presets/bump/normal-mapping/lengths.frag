#version 450
// |2 c - 1| for every texel of the normal map.
layout(location = 0) out float lengths;
uniform sampler2D nmap;
void main() { lengths = length(texelFetch(nmap, ivec2(gl_FragCoord.xy), 0).xyz * 2.0 - 1.0); }
