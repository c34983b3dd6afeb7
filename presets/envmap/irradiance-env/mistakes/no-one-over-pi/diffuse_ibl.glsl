// Diffuse image-based lighting, one lookup by the normal (000_c9f7e5de708ecbb3.txt, irradiance
// environment maps; see README): a Lambert surface under the irradiance E(N) reflects
//     L_o = albedo / pi * E(N)
// Shared by the teapot (diffuse.frag) and the furnace check (checks.frag), so the test measures
// the formula that renders.
vec3 diffuse_ibl(vec3 albedo, samplerCube irradiance, vec3 n) {
    return albedo * textureLod(irradiance, n, 0.0).rgb;
}
