#version 450
// Test passes of the clouds (CHECK selects):
//   CHECK 0, the slab: atmo_cloud_density over a 64 x 64 grid of heights (rows: 0..20 km) and
//     positions (columns, 40 km apart along x): .x the density, .w 1 where h is outside
//     [bottom, top] (the mask of the "0 outside the slab" check)
//   CHECK 1, ground-level sun transmittance: exp(-(b_R tau_R + b_M tau_M)) of the library's
//     16-sample march to the sun (clouds included) from ground points 0..40 km apart in x and z;
//     its mean must fall as cloud_factor rises
#define ATMO_CLOUDS 1
#include "volumetric/atmosphere.glsl"
#include "clouds.glsl"
layout(location = 0) out vec4 color;
void main() {
    vec2 f = (gl_FragCoord.xy - 0.5) / (frame.target.xy - 1.0);   // 0..1 over the image
#if CHECK == 0
    float h = f.y * 20000.0;
    vec3 p = vec3(f.x * 40000.0, ATMO_RE + h, 0.0);
    bool outside = !(params.cloud_bottom < h && h < params.cloud_top);
    color = vec4(atmo_cloud_density(p, h), h, 0.0, outside ? 1.0 : 0.0);
#else
    vec3 p = vec3(f.x * 40000.0, ATMO_RE, f.y * 40000.0);
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    color = vec4(atmo_transmittance(atmo_sun_depth(p, sun, params.sub_steps)), 1.0);
#endif
}
