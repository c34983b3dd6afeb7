#version 450
// The stored normal's length (1 where there is no geometry), for the unit-length test, and in
// the second channel whether the texel holds geometry (w = 1): without it a lookup that finds no
// geometry anywhere (a wrong mip, a wrong image) would read 1 everywhere and pass.
layout(location = 0) out vec2 normal_len;
uniform sampler2D normal;
void main() {
    vec4 n = texelFetch(normal, ivec2(gl_FragCoord.xy), 0);
    normal_len = vec2(n.w == 0.0 ? 1.0 : length(n.xyz), n.w);
}
