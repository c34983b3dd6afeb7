// The atmosphere library of the volumetric family: Rayleigh and Mie scattering coefficients,
// their phase functions, the exponential density profile, ray/sphere lengths and the
// single-scattering march with a march to the sun at every step
// (002_644d46bdce7e5305.txt L2172-2463; TECHNIQUES.md 3.14). The sky, the light shafts and the
// clouds all call atmo_scatter() below: an empty shafts scene and a cloud factor of 0 are the
// sky by construction, and their tests check it bit for bit.
//
// Hooks (define before including):
//   ATMO_CLOUDS              the includer defines float atmo_cloud_density(vec3 p, float h):
//                            extra Mie density (the clouds, L2395-2417), 0 outside the slab
//   ATMO_SUN_DEPTH_LUT       the march to the sun reads the baked table `sun_depth_lut`
//                            (sun_depth_lut.frag) instead of marching: live views only
//   ATMO_SUN_VISIBILITY(p)   an expression in [0, 1] for world point p: 1 lit, 0 in a shadow
//                            (the light shafts' shadow map); undefined = always lit
//
// Units are metres. World space has +y up and the ground at y = 0; the planet's centre is at
// (0, -ATMO_RE, 0), so a world point p is p + (0, ATMO_RE, 0) from it (the seed's
// "o.y += Re", L2423).
#ifndef PASSLAB_VOLUMETRIC_ATMOSPHERE_GLSL
#define PASSLAB_VOLUMETRIC_ATMOSPHERE_GLSL

// Typical constants for the earth (L2296-2316 table, L2360-2371 code). The table prints
// 21^{-6}, 6360^3, 6380^3: read as x10^-6 and x10^3, which is what the code writes.
const float ATMO_RE = 6360e3;                       // earth radius, m
const float ATMO_RA = 6380e3;                       // atmosphere radius from the centre, m
const float ATMO_HR = 8000.0;                       // Rayleigh scale height, m
const float ATMO_HM = 1800.0;                       // Mie scale height, m
const float ATMO_G  = 0.76;                         // Mie mean cosine (anisotropy)
const float ATMO_IS = 10.0;                         // sun intensity ("just a rendering example value")
const vec3  ATMO_BR = vec3(5.8e-6, 13.5e-6, 33.1e-6);   // Rayleigh scattering at sea level, 1/m (R, G, B)
const vec3  ATMO_BM = vec3(21e-6);                       // Mie scattering at sea level, 1/m
const float ATMO_PI = 3.14159265358979;

// ---- Phase functions (L2215-2217, L2250-2252) -------------------------------------------------
// mu = dot(view direction, direction towards the sun). Both integrate to 1 over the sphere.
//
// Rayleigh: P_R(mu) = 3/(16 pi) (1 + mu^2); the seed's 0.0596831 is 3/(16 pi) (L2455).
float atmo_phase_rayleigh(float mu) {
    return 3.0 / (16.0 * ATMO_PI) * (1.0 + mu * mu);
}

// Mie (Cornette-Shanks): P_M(mu) = 3/(8 pi) (1 - g^2)(1 + mu^2) / ((2 + g^2)(1 + g^2 - 2 g mu)^1.5).
// The slide (L2250) prints "+ 2 g mu", the code (L2456) "- 2.0 * g * Su": with mu the cosine
// between the view and the sun directions only the minus sign peaks towards the sun (forward
// scattering: the glow around the sun); the plus sign puts the glow opposite the sun. The code's
// 0.1193662 is 3/(8 pi).
float atmo_phase_mie(float mu, float g) {
    float g2 = g * g;
    return 3.0 / (8.0 * ATMO_PI) * ((1.0 - g2) * (1.0 + mu * mu)) /
           ((2.0 + g2) * pow(1.0 + g2 + 2.0 * g * mu, 1.5));
}

#ifdef ATMO_CLOUDS
float atmo_cloud_density(vec3 p, float h);   // defined by the includer (after this file is fine)
#endif

// ---- Densities (L2283-2293, L2395-2403) -----------------------------------------------------
// density(h) = density(0) exp(-h / H), per species; returned relative to sea level (the
// coefficients above carry the sea-level value). p is relative to the planet's centre.
void atmo_densities(vec3 p, out float rayleigh, out float mie) {
    float h = max(0.0, length(p) - ATMO_RE);
    rayleigh = exp(-(h / ATMO_HR));
    mie = exp(-(h / ATMO_HM));
#ifdef ATMO_CLOUDS
    // Clouds are "density modulations at the Mie scattering equation" (L2330).
    mie += atmo_cloud_density(p, h);
#endif
}

// ---- Ray lengths (L2405-2416) ---------------------------------------------------------------
// The seed's getRayLength: distance along d from p to the sphere of radius R, the far root if
// it is ahead, else the near one; -1 if the line misses. From inside the sphere that is the exit.
float atmo_ray_length(vec3 p, vec3 d, float R) {
    float b = dot(p, d), c = dot(p, p) - R * R, det = b * b - c;
    if (det < 0.0) return -1.0;
    det = sqrt(det);
    float ta = -b - det, tb = -b + det;
    float t0 = max(ta, tb), t1 = min(ta, tb);
    return (t0 >= 0.0) ? t0 : t1;
}

// Where a ray from outside a sphere first enters it (-1 if never ahead). The seed clips with
// getRayLength(o, d, Re) (L2468), which from above the ground is the *far* root (the ray's exit
// on the far side of the planet): a ray looking down would march through the earth. The near
// root is the ground.
float atmo_ray_enter(vec3 p, vec3 d, float R) {
    float b = dot(p, d), c = dot(p, p) - R * R, det = b * b - c;
    if (det < 0.0 || c < 0.0) return -1.0;
    float t = -b - sqrt(det);
    return t >= 0.0 ? t : -1.0;
}

// ---- Optical depth towards the sun (L2436-2443) ---------------------------------------------
// tau_s = integral of the densities from p to the atmosphere's top along the sun direction,
// sub_steps samples at j dLs (left sums, as the seed), x = Rayleigh, y = Mie.
vec2 atmo_sun_depth(vec3 p, vec3 sun, int sub_steps) {
    float Ls = atmo_ray_length(p, sun, ATMO_RA);
    if (Ls <= 0.0) return vec2(0.0);
    float dLs = Ls / float(sub_steps);
    vec2 depth = vec2(0.0);
    for (int j = 0; j < sub_steps; j++) {
        float r, m;
        atmo_densities(p + sun * (float(j) * dLs), r, m);
        depth += vec2(r, m) * dLs;
    }
    return depth;
}

// The optical depth towards the sun depends only on the height h and on mu_s = cos of the sun's
// zenith angle at p (the atmosphere is spherically symmetric), so it can be baked into a 2D
// table once per sun: u = sqrt(h / (R_A - R_E)) (rows dense near the ground), v = (mu_s + 1) / 2.
vec2 atmo_sun_lut_uv(vec3 p, vec3 sun) {
    float h = clamp(length(p) - ATMO_RE, 0.0, ATMO_RA - ATMO_RE);
    return vec2(sqrt(h / (ATMO_RA - ATMO_RE)), 0.5 * (dot(normalize(p), sun) + 1.0));
}
// The inverse: the point (relative to the centre) and the sun direction of a texel.
void atmo_sun_lut_point(vec2 uv, out vec3 p, out vec3 sun) {
    float mu = 2.0 * uv.y - 1.0;
    p = vec3(0.0, ATMO_RE + uv.x * uv.x * (ATMO_RA - ATMO_RE), 0.0);
    sun = vec3(sqrt(max(0.0, 1.0 - mu * mu)), mu, 0.0);
}
#ifdef ATMO_SUN_DEPTH_LUT
uniform sampler2D sun_depth_lut;
vec2 atmo_sun_depth_at(vec3 p, vec3 sun, int sub_steps) { return texture(sun_depth_lut, atmo_sun_lut_uv(p, sun)).rg; }
#else
vec2 atmo_sun_depth_at(vec3 p, vec3 sun, int sub_steps) { return atmo_sun_depth(p, sun, sub_steps); }
#endif

// Transmittance through optical depths tau = (Rayleigh, Mie): exp(-(b_R tau_R + b_M tau_M)),
// extinction = scattering for both (L2208-2209; the seed uses b_M for Mie extinction too).
vec3 atmo_transmittance(vec2 tau) {
    return exp(-(ATMO_BR * tau.x + ATMO_BM * tau.y));
}

// ---- Single scattering along a view ray (L2418-2459) ----------------------------------------
// The march of the seed's scatter(): `steps` samples along the view ray, each with its own
// march to the sun (`sub_steps` samples), A = exp(-(b_R (tau_Rs + tau_R) + b_M (tau_Ms + tau_M))),
// tau_R, tau_M the view ray's optical depth from the eye to the sample,
// sR += A dR, sM += A dM, and the phase functions applied once at the end:
//     L = I_s (sR b_R P_R(mu) + sM b_M P_M(mu)),   mu = dot(d, sun).
// origin: world position (m); d: unit view direction; max_len: the ray stops there too (the
// depth buffer of the light shafts, L2326; 1e30 for none); offset: where in each step the
// sample lies (0 = the seed's left sums; the Bayer offsets of interleaved sampling, L2333-2336).
// transmittance (out): exp of the view ray's whole optical depth (to attenuate a surface).
struct AtmoResult {
    vec3 radiance;         // I_s (sR b_R P_R(mu) + sM b_M P_M(mu))
    vec3 rayleigh;         // I_s sR b_R and I_s sM b_M: the in-scatter before its phase function
    vec3 mie;              // (interleaved sampling blurs these and applies the phases after)
    vec3 transmittance;
    float marched;         // the marched length, m
};

AtmoResult atmo_scatter(vec3 origin, vec3 d, vec3 sun, float max_len, float offset, int steps, int sub_steps) {
    vec3 o = origin + vec3(0.0, ATMO_RE, 0.0);
    AtmoResult res;
    // An eye above the atmosphere (sky-from-space, L2467-2497): start the march where the ray
    // enters it, so all `steps` samples fall inside; a ray that misses it sees black space.
    // (The seed moves the origin by the height above the top, `o += d * r`, L2487: the entry
    // point only for a ray straight down.)
    if (dot(o, o) > ATMO_RA * ATMO_RA) {
        float enter = atmo_ray_enter(o, d, ATMO_RA);
        if (enter < 0.0) {
            res.radiance = res.rayleigh = res.mie = vec3(0.0);
            res.transmittance = vec3(1.0);
            res.marched = 0.0;
            return res;
        }
        o += d * enter;
        max_len -= enter;
    }
    float L = atmo_ray_length(o, d, ATMO_RA);
    float ground = atmo_ray_enter(o, d, ATMO_RE);
    if (ground > 0.0) L = min(L, ground);
    L = max(0.0, min(L, max_len));
    float dL = L / float(steps);
    vec3 sR = vec3(0.0), sM = vec3(0.0);
    vec2 depth = vec2(0.0);
    for (int i = 0; i < steps; i++) {
        vec3 p = o + d * ((float(i) + offset) * dL);
        float dR, dM;
        atmo_densities(p, dR, dM);
        dR *= dL;
        dM *= dL;
        // Optical depth from the eye to the sample: the steps before plus `offset` of this one.
        // The seed adds the whole step first (L2433-2434 before L2444), attenuating the sample by
        // the part of its step it has not crossed yet: a bias of one step's optical depth, small
        // at 64 steps, 0.8 in blue for an 8-step horizontal ray; it would also make the sample
        // offset of interleaved sampling move the density but not the attenuation.
        vec2 depth_here = depth + offset * vec2(dR, dM);
        depth += vec2(dR, dM);
        vec2 depth_s = atmo_sun_depth_at(p, sun, sub_steps);
        vec3 A = atmo_transmittance(depth_s + depth_here);
#ifdef ATMO_SUN_VISIBILITY
        A *= ATMO_SUN_VISIBILITY(p - vec3(0.0, ATMO_RE, 0.0));
#endif
        sR += A * dR;
        sM += A * dM;
    }
    float mu = dot(d, sun);
    res.radiance = ATMO_IS * (sR * ATMO_BR * atmo_phase_rayleigh(mu) + sM * ATMO_BM * atmo_phase_mie(mu, ATMO_G));
    res.rayleigh = ATMO_IS * (sR * ATMO_BR);
    res.mie = ATMO_IS * (sM * ATMO_BM);
    res.transmittance = atmo_transmittance(depth);
    res.marched = L;
    return res;
}

// Direction towards the sun from elevation and azimuth (degrees; azimuth 0 = towards -z, the
// direction the default camera looks, growing towards +x).
vec3 atmo_sun_direction(float elevation_deg, float azimuth_deg) {
    float e = radians(elevation_deg), a = radians(azimuth_deg);
    return vec3(cos(e) * sin(a), sin(e), -cos(e) * cos(a));
}

#endif
