#version 450
// The stored normal's length (1 where there is no geometry), for the unit-length test.
layout(location = 0) out float normal_len;
uniform sampler2D normal;
void main() {
    vec4 n = texelFetch(normal, ivec2(gl_FragCoord.xy), 0);
    normal_len = n.w == 0.0 ? 1.0 : length(n.xyz);
}
