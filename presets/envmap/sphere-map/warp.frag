#version 450
// Generating a sphere map by warping a cube map (001_fe43b953f362fae7.txt L182-185): every
// texel of the disc is the chrome ball's normal n = (p, sqrt(1 - |p|^2)) at p = 2 uv - 1, seen
// orthographically by the eye; it reflects the eye ray to r = (2 n_z p, 2 n_z^2 - 1) in eye
// space (passes/envmap/sphere_map.glsl), which the map's eye frame turns into the world
// direction to look up. One lookup per texel: near the rim a texel covers a large solid angle
// (the whole back hemisphere is squeezed into the outer ring), so it aliases there.
#include "envmap/sphere_map.glsl"
#include "map_basis.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 sphere_map;
uniform samplerCube env;
void main() {
    vec3 r_eye = sphere_map_direction(uv);
    sphere_map = vec4(textureLod(env, sphere_map_basis() * r_eye, 0.0).rgb, 1.0);
}
