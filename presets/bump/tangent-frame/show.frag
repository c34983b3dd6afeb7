#version 450
// The mesh through its tangent frame: normal mapped with the tile map (n' = TBN (2 c - 1),
// 000_c9f7e5de708ecbb3.txt L2532-2553), or the frame itself as colours: T, B = (N x T) w, or
// the handedness w (orange +1, blue -1). VISIBLE hides the meshes not selected.
#include "bump/lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
uniform sampler2D nmap;
const vec3 kAlbedo = vec3(0.7, 0.66, 0.6);   // a light grey, so the glyph colours stand out
const float kShininess = 48.0, kSpecular = 0.3;
const vec3 kPlus = vec3(0.95, 0.55, 0.15), kMinus = vec3(0.15, 0.35, 0.9);   // w = +1 orange, -1 blue
void main() {
    if (!(VISIBLE)) discard;
    vec3 T = normalize(v_t), B = normalize(v_b), N = normalize(v_n);
    vec3 n = normalize(mat3(T, B, N) * (texture(nmap, v_uv * params.tiling).xyz * 2.0 - 1.0));
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    vec3 c = bump_blinn_phong(n, l, v, kAlbedo, kShininess, kSpecular);
    if (params.show == SHOW_TANGENT) c = T * 0.5 + 0.5;
    if (params.show == SHOW_BITANGENT) c = B * 0.5 + 0.5;
    if (params.show == SHOW_HANDEDNESS) c = dot(B, cross(N, T)) < 0.0 ? kMinus : kPlus;
    hdr = vec4(c, 1.0);
}
