// Sphere mapping (001_fe43b953f362fae7.txt L151-189): the map is the orthographic image of a
// chrome ball seen by the eye; its centre reflects back to the eye, the back of the world maps
// onto the outer ring (the singularity, L167-169). 001 gives no formula; this is the classic
// OpenGL GL_SPHERE_MAP one (docs/catalogue.md pitfall), for an eye-space reflection vector r (the eye
// looks down -z, so "back to the eye" is r = +z):
//     m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2),     (s, t) = r.xy / m + 0.5
// Derivation: the ball normal at image point p = 2 (s, t) - 1 is n = (p, sqrt(1 - |p|^2)); the
// eye ray v = (0, 0, -1) reflects to r = v - 2 (n.v) n = (2 n_z p, 2 n_z^2 - 1), and then
// m = 4 n_z, r.xy / m = p / 2. A direction at angle alpha from +z has r_z = cos(alpha) =
// 2 n_z^2 - 1, so it lands at radius |p| / 2 = sin(alpha / 2) / 2.
// Image convention (Vulkan, t = 0 at the top): the map is stored upright, eye +y at the top, so
// the stored v coordinate is 1 - t. OpenGL's t = 0 is the bottom row and needs no flip.
#ifndef PASSLAB_SPHERE_MAP_GLSL
#define PASSLAB_SPHERE_MAP_GLSL
vec2 sphere_map_coord(vec3 r) {
    float m = 2.0 * sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0));
    vec2 st = r.xy / m + 0.5;
    return vec2(st.x, 1.0 - st.y);
}

// The inverse: the eye-space direction stored at image coordinate uv (inside the disc |p| <= 1;
// outside it the nearest rim point, so that filtering at the rim does not pull in black).
vec3 sphere_map_direction(vec2 uv) {
    vec2 p = vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y);
    float l = length(p);
    if (l > 1.0) p /= l;
    float nz = sqrt(max(1.0 - dot(p, p), 0.0));
    return vec3(2.0 * nz * p, 1.0 - 2.0 * nz * nz);
}
#endif
