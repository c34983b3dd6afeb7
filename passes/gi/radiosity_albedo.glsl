// Albedo of a radiosity patch's surface: the Cornell values, or the closed-box test's uniform
// params.rho on every surface (there the exact answer is known: L = Le / (1 - rho)).
#ifndef PASSLAB_GI_RADIOSITY_ALBEDO_GLSL
#define PASSLAB_GI_RADIOSITY_ALBEDO_GLSL

#include "gi/radiosity_patches.glsl"

vec3 radiosity_albedo(RadSurface s) {
    return params.closed ? vec3(params.rho) : cornell_albedo(s.mesh, s.instance);
}

#endif
