// A procedural environment for the envmap presets (nothing downloaded): a sky whose blue
// deepens towards the zenith, a warm horizon band, a sun disc with a glow, and a darker ground
// with a faint grid so reflections show orientation. Radiance, linear.
#ifndef PASSLAB_SKY_GLSL
#define PASSLAB_SKY_GLSL
vec3 sky_radiance(vec3 d, vec3 sun_dir, float sun_intensity) {
    d = normalize(d);
    vec3 sun = normalize(sun_dir);
    if (d.y < 0.0) {
        // Ground: the direction hits y = -1; a 1-unit grid, darker with distance.
        vec2 g = d.xz / max(-d.y, 1e-3);
        vec2 f = abs(fract(g) - 0.5);
        float line = smoothstep(0.47, 0.5, max(f.x, f.y)) * exp(-0.05 * length(g));
        return mix(vec3(0.18, 0.16, 0.13), vec3(0.35, 0.3, 0.25), line) * (0.6 + 0.4 * exp(-8.0 * -d.y));
    }
    vec3 zenith = vec3(0.12, 0.3, 0.75), horizon = vec3(0.85, 0.75, 0.6);
    vec3 c = mix(horizon, zenith, pow(d.y, 0.45));
    float cos_sun = dot(d, sun);
    c += sun_intensity * (smoothstep(0.9995, 0.9998, cos_sun) * vec3(1.0, 0.95, 0.85) * 20.0 + pow(max(cos_sun, 0.0), 64.0) * vec3(1.0, 0.7, 0.4) * 0.6);
    return c;
}
#endif
