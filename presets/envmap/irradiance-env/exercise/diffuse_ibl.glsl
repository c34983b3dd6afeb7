// EXERCISE — diffuse image-based lighting, one lookup by the normal (001_fe43b953f362fae7.txt
// L345-353, N as lookup direction). Shared by the teapot (diffuse.frag) and the furnace check
// (checks.frag), so the tests measure the formula that renders. TODO 1 is in
// exercise/envmap/irradiance_convolve.frag.
vec3 diffuse_ibl(vec3 albedo, samplerCube irradiance, vec3 n) {
    // TODO 2: the radiance a Lambert surface of reflectance albedo reflects under the irradiance
    // E(n) looked up in the map (textureLod(irradiance, n, 0.0)). The Lambert BRDF is constant,
    // but not albedo itself: what must it be for the surface to reflect no more than it receives
    // (shading/lambert, 000 L1011)?
    return vec3(0.0);
}
