#version 450
// Volumetric light scattering (light shafts): the sky's march, stopped at the depth buffer, with
// the sun's light shadowed by the shadow map at every step (002_644d46bdce7e5305.txt L2317-2331).
//
//   "as volumetric light scattering effect variant the length of your ray stops simply on the
//    respective value from your depth buffer" (L2326)
//       L = min(exit of the atmosphere, ground, distance to the depth buffer's surface)
//   "for each main ray raymarching step, you starting a new raymarching subprocess with a ray ...
//    into the direction to your current main light source" (L2327): the library's 16-sample
//    march to the sun, times the shadow map's visibility of the step's point
//   "Then apply the phase functions to the accumulated equation results" (L2331): once, at the end
//
// Outputs the in-scatter L_in and the view ray's transmittance T (composite.frag adds
// L_surface T; with SHAFTS_SPLIT the Rayleigh and Mie parts before their phase functions).
// SHAFTS_EXCESS (test only): L_in(depth-limited) - L_in(unlimited), which can
// never be positive: the limited ray is a prefix of the unlimited one.
// Shared with interleaved-sampling, which sets SHAFTS_OFFSET (where in each step the sample lies:
// default 0, the seed's left sums) and SHAFTS_STEPS (default params.steps).
#include "volumetric/sky_view.glsl"
#include "volumetric/interleave.glsl"
#include "shadows/shadow_map.glsl"
uniform sampler2D shadow;
uniform sampler2D depth;

// How much the shadow map blocks the sun (params.shadowing; the excess pass also marches with 0).
float shafts_shadowing = 1.0;

// Sun visibility of a world point: 1 lit, 0 behind a monolith (as seen from the sun). A point
// outside the map is lit (shadow_map.glsl's convention): the sky's march mostly runs there.
float shafts_sun_visibility(vec3 p) {
    vec3 coord = shadow_project(cameras.sun.view_proj, p);
    coord.z -= 2e-4;                       // 8 m of the sun camera's 40 km depth range: no self-shadowing of the ground
    return mix(1.0, shadow_nearest(shadow, coord), shafts_shadowing);
}
#define ATMO_SUN_VISIBILITY(p) shafts_sun_visibility(p)
#include "volumetric/atmosphere.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 inscatter;
layout(location = 1) out vec4 transmit;
#ifdef SHAFTS_SPLIT
layout(location = 2) out vec4 inscatter_mie;   // SHAFTS_SPLIT: location 0 holds the Rayleigh part, this the Mie part, both before their phase
#endif

// The ray's length from the depth buffer: the distance from the eye to the surface the pixel
// sees, or "no limit" (1e30) where the depth is the far plane's (the sky).
float shafts_ray_limit(vec3 eye) {
    ivec2 size = textureSize(depth, 0);
    float z = texelFetch(depth, min(ivec2(uv * vec2(size)), size - 1), 0).r;
    if (z >= 1.0) return 1e30;
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, z, 1.0);
    return length(w.xyz / w.w - eye);
}

#ifndef SHAFTS_OFFSET
#define SHAFTS_OFFSET 0.0
#endif
#ifndef SHAFTS_STEPS
#define SHAFTS_STEPS params.steps
#endif

void main() {
    shafts_shadowing = params.shadowing;
    vec3 eye = frame.camera_pos.xyz;
    vec3 d = sky_camera_direction(uv);
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    AtmoResult a = atmo_scatter(eye, d, sun, shafts_ray_limit(eye), SHAFTS_OFFSET, SHAFTS_STEPS, params.sub_steps);
#ifdef SHAFTS_EXCESS
    AtmoResult u = atmo_scatter(eye, d, sun, 1e30, 0.0, params.steps, params.sub_steps);
    // alpha: 1 where the comparison is meaningful at this step count: the depth buffer cut the ray
    // to under half (monoliths, near ground) or not at all (sky). Between the two (ground far
    // away, where the flat ground and the planet's sphere end the rays almost together) both
    // marches cover nearly the same path on slightly different grids, and the left sums'
    // discretisation error (~1/steps of L_in) is larger than the tail being compared.
    // A limited ray longer than the unlimited one is always counted: that is the bug to catch.
    float meaningful = (a.marched < 0.5 * u.marched || a.marched >= u.marched) ? 1.0 : 0.0;
    inscatter = vec4(a.radiance - u.radiance, meaningful);
#elif defined(SHAFTS_SPLIT)
    inscatter = vec4(a.rayleigh, 1.0);
    inscatter_mie = vec4(a.mie, 1.0);
#else
    inscatter = vec4(a.radiance, 1.0);
#endif
    // alpha: ln of the length marched (>= 1 m), the edge-stopping "depth" of interleaved
    // sampling's cross-bilateral blur (tile_blur.frag)
#ifdef SHAFTS_EXCESS
    // .x: what the shadows remove from this ray's in-scatter (the same march without them minus
    // with them, >= 0 by construction; its mean over the image must be clearly > 0: shafts exist)
    shafts_shadowing = 0.0;
    AtmoResult unshadowed = atmo_scatter(eye, d, sun, shafts_ray_limit(eye), SHAFTS_OFFSET, SHAFTS_STEPS, params.sub_steps);
    transmit = vec4(dot(unshadowed.radiance - a.radiance, vec3(1.0 / 3.0)), 0.0, 0.0, 1.0);
#else
    // alpha: ln of the length marched (>= 1 m), the edge-stopping "depth" of interleaved
    // sampling's cross-bilateral blur (tile_blur.frag)
    transmit = vec4(a.transmittance, log(max(a.marched, 1.0)));
#endif
}
