#version 450
// EXERCISE — a mirror object lit by the environment through the sphere map. TODO 1 and 2 are in
// exercise/envmap/sphere_map.glsl; TODO 3 is here.
//     passlab run   envmap/sphere-map --exercise presets/envmap/sphere-map/exercise
//     passlab grade envmap/sphere-map --exercise presets/envmap/sphere-map/exercise
// view_reflection() (passes/envmap/reflect.glsl) gives R = V - 2 (N.V) N in world space
// (001_fe43b953f362fae7.txt L251-260). The map is made for one eye frame: sphere_map_basis()
// (map_basis.glsl) is its world-from-eye rotation (columns = the eye's axes in world space).
// lookup = cube_map samples the cube map by R instead, for comparison.
#include "envmap/sphere_map.glsl"
#include "map_basis.glsl"
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
uniform sampler2D sphere_map;
void main() {
    vec3 R = view_reflection(v_world, v_normal);
    // TODO 3: OpenGL's sphere-map texgen uses the EYE-space reflection vector (001 L181), and the
    // map's eye frame is sphere_map_basis(), which goes from eye to world. Express R in that eye
    // frame (what is the inverse of a rotation?) before it reaches sphere_map_coord().
    vec3 r_eye = vec3(0.0, 0.0, 1.0);
    vec3 c = params.lookup == LOOKUP_CUBE_MAP ? texture(env, R).rgb : texture(sphere_map, sphere_map_coord(r_eye)).rgb;
    hdr = vec4(params.tint * c, 1.0);
}
