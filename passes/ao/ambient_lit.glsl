// The screen-space AO presets' shading of a G-buffer pixel: a sky-to-ground ambient term
// (003_cfc3b5b225ddab3d.txt L334: "darken the environment lighting by the occlusion amount";
// 004_9a40ad89bdfc582a.txt L719: "use in the lighting model as a factor") times the visibility,
// plus a weak key light so shapes stay readable without it. Shared by ao/ssao and ao/ssao-disk.
#ifndef PASSLAB_AO_AMBIENT_LIT_GLSL
#define PASSLAB_AO_AMBIENT_LIT_GLSL

const vec3 kAoBackground = vec3(0.6, 0.7, 0.85);  // where the G-buffer holds no geometry

// n_view: the view-space normal (G-buffer), visibility in [0, 1].
vec3 ao_ambient_lit(vec3 n_view, float visibility) {
    vec3 n_world = normalize(transpose(mat3(frame.view)) * n_view);
    vec3 ambient = mix(vec3(0.3, 0.28, 0.27), vec3(0.55, 0.6, 0.7), 0.5 + 0.5 * n_world.y);
    float key = max(dot(n_world, normalize(vec3(0.4, 0.8, 0.3))), 0.0);
    return ambient * visibility + 0.25 * key * vec3(1.0, 0.95, 0.85);
}
#endif
