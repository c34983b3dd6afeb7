// Shadertoy's keyboard texture: key 65 ('A') in its three rows (down, pressed this frame,
// toggled) as red, green and blue; key 66 ('B', never held) as alpha, which must stay 0.
// texelFetch, as Shadertoy's keyboard examples read it.
void mainImage(out vec4 c, in vec2 p) {
    float down = texelFetch(iChannel0, ivec2(65, 0), 0).x;
    float pressed = texelFetch(iChannel0, ivec2(65, 1), 0).x;
    float toggled = texelFetch(iChannel0, ivec2(65, 2), 0).x;
    float other = texelFetch(iChannel0, ivec2(66, 0), 0).x + texelFetch(iChannel0, ivec2(66, 1), 0).x;
    c = vec4(down, pressed, toggled, 1.0) * (1.0 - other);
}
