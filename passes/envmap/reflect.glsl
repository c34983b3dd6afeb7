// The mirror direction of the view ray at a surface point, in world space (001_fe43b953f362fae7.txt
// L251-260, "angle of incidence = angle of reflection"):
//     R = V - 2 (N.V) N,   V = normalize(p - eye) (from the eye to the surface), N the unit normal
// World space, because the environment maps (cube, sphere-map eye frame, paraboloids) are built in
// world axes: an eye-space R would need the inverse view rotation first (catalogue pitfall).
// Shared by the mirror/glossy shaders of envmap/cube-map-dynamic, sphere-map,
// dual-paraboloid-map and specular-prefiltered-env.
#ifndef PASSLAB_ENVMAP_REFLECT_GLSL
#define PASSLAB_ENVMAP_REFLECT_GLSL
vec3 view_reflection(vec3 world_pos, vec3 normal) {
    vec3 n = normalize(normal), V = normalize(world_pos - frame.camera_pos.xyz);
    return V - 2.0 * dot(n, V) * n;
}
#endif
