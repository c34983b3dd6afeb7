// The eye frame a sphere map is made for (world-from-eye rotation; the eye looks down its -z).
// Sphere maps are view dependent (001_fe43b953f362fae7.txt L186-187): map_view = camera
// re-warps the map for the current view every frame; map_view = fixed keeps the one made for an
// eye in direction params.fixed_eye from the object, like a photograph of a chrome ball (L185).
#include "common/camera.glsl"
mat3 sphere_map_basis() {
    mat3 world_to_eye = params.map_view == MAP_VIEW_CAMERA ? mat3(frame.view)
                      : mat3(look_at(normalize(params.fixed_eye), vec3(0.0), vec3(0.0, 1.0, 0.0)));
    return transpose(world_to_eye);  // a rotation: its inverse is its transpose
}
