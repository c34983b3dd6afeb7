#version 450
// The rendered texture read back texel by texel: what the first pass stored, exactly.
layout(location = 0) out vec4 rt_copy;
uniform sampler2D rt_color;
void main() { rt_copy = texelFetch(rt_color, ivec2(gl_FragCoord.xy), 0); }
