#version 450
// Environment-map bump mapping in world space (000_c9f7e5de708ecbb3.txt L2569-2585, 001's
// "EMNM", 001_fe43b953f362fae7.txt L922-936):
//   per vertex:   V to world space; the tangent-to-world frame (T, B, N)   (bump/tangent_space.vert)
//   per fragment: interpolate and renormalise V and the frame; n' = (T B N) (2 texture(s, t) - 1);
//                 R = V - 2 (n'.V) n' in world space; C = cubemap(R)        (a dependent texture read)
//   colour = mix(decal, C, reflectivity)  (as presets/envmap/cube-env-reflection)
// map: tiles (the bevelled tile normal map), flat (the map (0.5, 0.5, 1) stored exactly, rgba16f),
// flat8 (the same in 8 bits: 128/255 decodes to 0.0039, a tilt of 0.0055 rad),
// geometric (no map: the interpolated normal, cube-env-reflection's shader exactly).
// VISIBLE hides the model not selected. R comes from passes/envmap/reflect.glsl (view_reflection,
// 001 L251-260), the envmap family's one copy.
#include "envmap/reflect.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
uniform sampler2D nmap;
uniform sampler2D nmap_flat;
uniform sampler2D nmap_flat8;
void main() {
    if (!(VISIBLE)) discard;
    mat3 tbn = mat3(normalize(v_t), normalize(v_b), normalize(v_n));
    vec3 c = params.map == MAP_FLAT ? texture(nmap_flat, v_uv).xyz : params.map == MAP_FLAT8 ? texture(nmap_flat8, v_uv).xyz : texture(nmap, v_uv * params.tiling).xyz;
    vec3 n = params.map == MAP_GEOMETRIC ? normalize(v_n) : normalize(tbn * (c * 2.0 - 1.0));
    vec3 V = normalize(frame.camera_pos.xyz - v_world), R = V - 2.0 * dot(n, V) * n;   // V - 2 (n'.V) n', V from the eye to the surface
    vec3 col = mix(params.decal, texture(env, R).rgb, params.reflectivity);
    if (params.show == SHOW_NORMALS) col = n * 0.5 + 0.5;
    if (params.show == SHOW_REFLECTION) col = R * 0.5 + 0.5;
    hdr = vec4(col, 1.0);
}
