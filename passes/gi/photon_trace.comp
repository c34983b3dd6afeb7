#version 450
// Pass 1 of photon mapping (000_c9f7e5de708ecbb3.txt L5077-5089): "shoot photons from light
// source; store particles hitting diffuse surfaces".
//
// Emission: the spot of gi/cornell.glsl radiates I(w) W/sr inside a 60-degree cone. Photon p takes
// a jittered stratum of the cone's solid angle (cos theta in [cos 60, 1], phi in [0, 2 pi): a
// 256 x 256 grid) and carries flux Phi_p = I(w_p) * Omega / N, Omega = 2 pi (1 - cos 60) = pi, so
// the N photons together carry the spot's flux  Phi = integral of I over the cone.
// Transport: at every diffuse hit the photon is stored, then survives with probability
// q = max(albedo) (Russian roulette) and leaves in a cosine-distributed direction with flux
// Phi * albedo / q: the expected flux leaving a hit is albedo times what arrived (the check
// "stored flux of bounce 2 = emitted x first-hit albedo").
layout(local_size_x = 64) in;

#include "gi/photon_map.glsl"
#include "gi/radiosity_trace.glsl"
#include "gi/radiosity_albedo.glsl"
#include "common/hash.glsl"
#include "common/sampling.glsl"

layout(std430) writeonly buffer Photons { vec4 rec[]; } photons;

void store(int slot, vec3 x, vec3 n, vec3 w, vec3 flux) {
    photons.rec[3 * slot] = vec4(x, flux.r);
    photons.rec[3 * slot + 1] = vec4(n, flux.g);
    photons.rec[3 * slot + 2] = vec4(w, flux.b);
}

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= PM_PHOTONS) return;
    int walls = params.closed ? RAD_WALLS : CORNELL_WALLS;
    // Emission: jittered stratum (i, j) of (cos theta, phi) over the cone.
    const int side = 256;
    vec3 h = hash_pcg3(vec3(p, 1, 17));
    float cos_t = mix(CORNELL_CONE_OUTER, 1.0, (float(p % side) + h.x) / float(side));
    float phi = 6.28318530718 * (float(p / side) + h.y) / float(side);
    float sin_t = sqrt(max(0.0, 1.0 - cos_t * cos_t));
    vec3 w = basis_from_normal(CORNELL_LIGHT_DIR) * vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
    const float cone_solid_angle = 6.28318530718 * (1.0 - CORNELL_CONE_OUTER);
    vec3 flux = params.light * cornell_light_intensity(w) * cone_solid_angle / float(PM_PHOTONS);
    vec3 x = CORNELL_LIGHT_POS;
    for (int b = 0; b < PM_BOUNCES; ++b) {
        int slot = p * PM_BOUNCES + b;
        RadHit hit = flux.r + flux.g + flux.b > 0.0 ? radiosity_trace(x, w, walls) : RadHit(false, 0.0, -1, vec3(0.0), false);
        if (!hit.found || hit.back) {
            store(slot, vec3(1e9), vec3(0.0), vec3(0.0), vec3(0.0));  // left the box (or absorbed before)
            flux = vec3(0.0);
            continue;
        }
        RadSurface s = radiosity_surface(hit.surface);
        vec3 n = radiosity_world_normal(s);
        x = x + hit.t * w;
        store(slot, x, n, w, flux);
        // Russian roulette: survive with q = max albedo, the survivor's flux scaled by albedo / q.
        vec3 albedo = radiosity_albedo(s);
        float q = max(albedo.r, max(albedo.g, albedo.b));
        vec3 u = hash_pcg3(vec3(p, b, 29));
        if (u.z >= q) {
            flux = vec3(0.0);
            continue;
        }
        flux *= albedo / q;
        float st = sqrt(u.x), ct = sqrt(max(0.0, 1.0 - u.x)), ph = 6.28318530718 * u.y;
        w = basis_from_normal(n) * vec3(st * cos(ph), st * sin(ph), ct);
        x += n * 1e-4;
    }
}
