#version 450
// A mirror object lit by the environment through the sphere map: R = V - 2 (N.V) N in world
// space (001_fe43b953f362fae7.txt L251-260), turned into the map's eye frame (OpenGL's sphere-map
// texgen uses the eye-space reflection vector, 001 L181) and looked up at
//     (s, t) = r.xy / m + 0.5,  m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2)
// or, for comparison (lookup = cube_map), the cube map directly by R.
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
    vec3 r_eye = transpose(sphere_map_basis()) * R;
    vec3 c = params.lookup == LOOKUP_CUBE_MAP ? texture(env, R).rgb : texture(sphere_map, sphere_map_coord(r_eye)).rgb;
    hdr = vec4(params.tint * c, 1.0);
}
