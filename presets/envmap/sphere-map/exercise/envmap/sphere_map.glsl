// EXERCISE — sphere mapping (001_fe43b953f362fae7.txt L151-189): the map is the orthographic
// image of a chrome ball seen by the eye; its centre reflects back to the eye, the back of the
// world maps onto the outer ring (the singularity, L167-169). This file shadows
// passes/envmap/sphere_map.glsl; exercise/mirror.frag holds TODO 3.
//     passlab run   envmap/sphere-map --exercise presets/envmap/sphere-map/exercise
//     passlab grade envmap/sphere-map --exercise presets/envmap/sphere-map/exercise
// 001 gives no formula; the preset uses the classic OpenGL GL_SPHERE_MAP one (README "The
// formula"), for an eye-space reflection vector r (the eye looks down -z, so "back to the eye"
// is r = +z). The ball normal at image point p = 2 (s, t) - 1 is n = (p, sqrt(1 - |p|^2)); the
// eye ray v = (0, 0, -1) reflects to r = v - 2 (n.v) n.
// Image convention (Vulkan, t = 0 at the top): the map is stored upright, eye +y at the top, so
// the stored v coordinate is 1 - t. OpenGL's t = 0 is the bottom row and needs no flip.
#ifndef PASSLAB_SPHERE_MAP_GLSL
#define PASSLAB_SPHERE_MAP_GLSL
vec2 sphere_map_coord(vec3 r) {
    // TODO 1: the GL_SPHERE_MAP texture coordinate of the eye-space direction r (001 L181):
    //     m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2),     (s, t) = r.xy / m + 0.5
    // (work out which term the + 1 belongs to from the derivation above: m must equal 4 n_z),
    // then return the stored coordinate (s, 1 - t).
    return vec2(0.5);
}

// The inverse: the eye-space direction stored at image coordinate uv (inside the disc |p| <= 1;
// outside it the nearest rim point, so that filtering at the rim does not pull in black).
vec3 sphere_map_direction(vec2 uv) {
    vec2 p = vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y);
    float l = length(p);
    if (l > 1.0) p /= l;
    // TODO 2: the chrome ball's normal at p, n = (p, sqrt(1 - |p|^2)) (clamp the square root's
    // argument at 0 on the rim), and the eye ray v = (0, 0, -1) reflected about it (001 L182-184,
    // "warping a cube map"): r = v - 2 (n.v) n. Written out per component, r.xy is a multiple of
    // p and r.z depends on n_z only. The centre (p = 0) must give r = +z, the rim r = -z.
    return vec3(0.0, 0.0, 1.0);
}
#endif
