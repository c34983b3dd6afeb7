#version 450
// Surface radiance of the light-shaft scene: sunlight through the atmosphere (per vertex,
// monoliths.vert), the shadow map, Lambert with albedo 0.3, plus a
// constant skylight term. The view ray's attenuation and in-scatter are added later, per pixel,
// by the shafts pass (L = L_surface T + L_in).
#include "volumetric/atmosphere.glsl"
#include "shadows/shadow_map.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_sun_transmittance;
layout(location = 0) out vec4 color;
uniform sampler2D shadow;
void main() {
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    vec3 n = normalize(v_normal);
    float ndl = max(dot(n, sun), 0.0);
    vec3 coord = shadow_project(cameras.sun.view_proj, v_world + n * 2.0);
    float lit = shadow_nearest(shadow, coord);
    const float albedo = 0.3;
    vec3 L = albedo / ATMO_PI * ATMO_IS * v_sun_transmittance * ndl * lit + albedo * vec3(0.02, 0.035, 0.06);
    color = vec4(L, 1.0);
}
