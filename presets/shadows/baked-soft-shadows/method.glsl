// baked-soft-shadows: the ground looks its visibility up in the baked lightmap (bilinear: the
// filtering smooths texels, the softness itself comes from the area samples, L4426-4428). The
// casters are not baked (lit, their own N.L only): static shadows on a static receiver.
uniform sampler2D lightmap;
float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    if (abs(p.y) > 1e-4) return 1.0;
    return texture(lightmap, p.xz / 6.0 + 0.5).r;
}
