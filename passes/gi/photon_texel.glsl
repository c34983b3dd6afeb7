// Where photon mapping estimates the light: the centre of light-map texel p (the patches of
// gi/radiosity_patches.glsl at the resolution the preset defines), and which photons count there.
// Shared by the grid gather and the brute-force check, so the two differ only in which records
// they visit.
#ifndef PASSLAB_GI_PHOTON_TEXEL_GLSL
#define PASSLAB_GI_PHOTON_TEXEL_GLSL

#include "gi/radiosity_patches.glsl"

void photon_texel(int p, out RadSurface s, out vec3 x, out vec3 n) {
    s = radiosity_surface(radiosity_surface_of_patch(p));
    int local = p - s.first;
    vec2 ab = (vec2(local % s.n, local / s.n) + 0.5) / float(s.n);
    x = (radiosity_world_from_object(s) * vec4(radiosity_object_point(s, ab), 1.0)).xyz;
    n = radiosity_world_normal(s);
}

// The flux a record (a = position, flux.r; b = normal, flux.g; d = incoming, flux.b) adds at x:
// inside the sphere of radius r, and on this side of the surface (not the photons on the other
// face of a block edge or the wall behind a corner).
vec3 photon_contribution(vec4 a, vec4 b, vec4 d, vec3 x, vec3 n, float r) {
    vec3 dx = a.xyz - x;
    return dot(dx, dx) < r * r && dot(b.xyz, n) > 0.5 ? vec3(a.w, b.w, d.w) : vec3(0.0);
}

// L = (rho / pi) * sum Phi_p / (pi r^2)
vec3 photon_radiance(vec3 albedo, vec3 flux, float r) { return albedo / 3.14159265 * flux / (3.14159265 * r * r); }

#endif
