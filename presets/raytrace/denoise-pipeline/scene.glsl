// The denoising pipeline's scene: the default teapot on a floor under a sky and a disk area
// light, traced through the host BVH (raytrace/bvh.glsl). One path sample of a pixel is one
// ambient-occlusion ray (sky light, cosine-distributed) and one shadow ray to a random point on
// the light: its expectation is the converged image, its variance the noise the stages remove.
#ifndef DENOISE_SCENE_GLSL
#define DENOISE_SCENE_GLSL
#include "raytrace/bvh.glsl"
#include "common/hash.glsl"
#include "common/sampling.glsl"

const uint MESH_TEAPOT = 0u, MESH_FLOOR = 1u;  // order of the buffer's `meshes`
// The teapot generator centres its bounding box: its base is 0.4828 below its origin
// (tests/graphs/bvh/scene.glsl).
const vec3 kTeapotOffset = vec3(0.0, 0.4828, 0.0);
const vec3 kLightCentre = vec3(-2.2, 2.4, 1.4);
const float kLightRadius = 0.6;
const vec3 kSky = vec3(0.42, 0.48, 0.58), kLight = vec3(1.0, 0.92, 0.8) * 0.8;
const float kAoDistance = 4.0;  // beyond this a ray reaches the sky
const float kRayOffset = 1e-3;  // off the surface along n (teapot 4096 triangles: flat facets)

mat4 object_from_world(uint mesh) {
    return mesh == MESH_TEAPOT ? mat4(vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0), vec4(-kTeapotOffset, 1)) : mat4(1.0);
}

bool scene_occluded(vec3 o, vec3 d, float tmax) {
    return pl_bvh_occluded(MESH_TEAPOT, object_from_world(MESH_TEAPOT), o, d, 0.0, tmax) ||
           pl_bvh_occluded(MESH_FLOOR, object_from_world(MESH_FLOOR), o, d, 0.0, tmax);
}

vec3 albedo_of(float id) { return id < 0.5 ? vec3(0.85, 0.45, 0.25) : vec3(0.72, 0.72, 0.7); }

// One sample of the outgoing radiance at p (normal n, albedo a), random numbers r in [0, 1)^4:
//   L = a (sky V(w_cos) + E cos(theta_l) V(light point))
vec3 scene_sample(vec3 p, vec3 n, vec3 a, vec4 r) {
    vec3 o = p + kRayOffset * n;
    // Sky: one cosine-distributed direction (Malley), open = the sky's radiance.
    float s = sqrt(r.x), phi = 6.2831853 * r.y;
    vec3 w = basis_from_normal(n) * vec3(s * cos(phi), s * sin(phi), sqrt(max(0.0, 1.0 - r.x)));
    vec3 sky = scene_occluded(o, w, kAoDistance) ? vec3(0.0) : kSky;
    // Light: a uniform point on the disk facing the origin.
    vec3 axis = normalize(-kLightCentre);
    float rr = kLightRadius * sqrt(r.z), pa = 6.2831853 * r.w;
    vec3 q = kLightCentre + basis_from_normal(axis) * vec3(rr * cos(pa), rr * sin(pa), 0.0);
    vec3 to_light = q - o;
    float dist = length(to_light), cos_l = max(dot(n, to_light / dist), 0.0);
    vec3 direct = cos_l > 0.0 && !scene_occluded(o, to_light / dist, dist) ? kLight * cos_l : vec3(0.0);
    return a * (sky + direct);
}

vec4 scene_random(ivec2 px, uint frame_index, uint k) { return vec4(hash_pcg3(vec3(px, float(frame_index * 97u + k))), hash_pcg(vec3(px.yx, float(frame_index * 89u + k + 7u)))); }
#endif
