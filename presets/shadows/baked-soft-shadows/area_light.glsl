// The area light of baked-soft-shadows: a disk of radius params.light_size facing the origin,
// centred on the camera `light`'s eye; visibility of it from a ground point = the fraction of
// AREA_SAMPLES shadow rays towards points spread evenly over the disk (a Vogel spiral: the
// same fixed pattern for every texel, so the bake is noise-free and repeatable) that reach it.
// 000_c9f7e5de708ecbb3.txt L4424-4428: per texel, cast rays to each light; soft shadows must
// sample the area light source, not come from texture filtering alone; L4432-4441: 1 sample
// (hard) vs. n samples (soft).
#include "raytrace/bvh.glsl"
#include "shadows/scene.glsl"

bool area_ray_occluded(vec3 o, vec3 d, float tmax) {
    for (int k = 0; k < 2; ++k)   // BVH mesh k = object k + 1 (box, ball)
        if (pl_bvh_occluded(uint(k), inverse(shadow_model(k + 1)), o, d, 1e-4, tmax)) return true;
    return false;
}

float area_light_visibility(vec3 p, float radius) {
    vec3 centre = cameras.light.position.xyz;
    vec3 axis = normalize(centre);   // the disk faces the origin
    vec3 u = normalize(abs(axis.y) < 0.99 ? cross(axis, vec3(0, 1, 0)) : cross(axis, vec3(1, 0, 0)));
    vec3 v = cross(axis, u);
    int lit = 0;
    for (int k = 0; k < AREA_SAMPLES; ++k) {
        float r = radius * sqrt((float(k) + 0.5) / float(AREA_SAMPLES));   // equal-area rings
        float a = 2.39996323 * float(k);                                    // the golden angle
        vec3 q = centre + r * (cos(a) * u + sin(a) * v);
        vec3 d = q - p;
        float dist = length(d);
        if (!area_ray_occluded(p, d / dist, dist)) ++lit;
    }
    return float(lit) / float(AREA_SAMPLES);
}
