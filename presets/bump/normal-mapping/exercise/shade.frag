#version 450
// EXERCISE — fill in the two TODO blocks; as shipped the texel itself is used as the normal.
//     passlab run   bump/normal-mapping --exercise presets/bump/normal-mapping/exercise
//     passlab grade bump/normal-mapping --exercise presets/bump/normal-mapping/exercise
// Normal mapping (000_c9f7e5de708ecbb3.txt L2490-2553; 001_fe43b953f362fae7.txt L463-490):
// the map's RGB decoded to a tangent-space normal n' = 2 c - 1, brought to world space with the
// interpolated frame (T, B, N), then Blinn-Phong with it: max(l.n', 0) and max(h.n', 0)^s.
// (000 transforms l and h into tangent space per vertex instead; the result is the same up to
// interpolation — here the frame is interpolated and l, h stay in world space.)
// The lighting is the bump family's one copy (passes/bump/lighting.glsl).
#include "bump/lighting.glsl"
#include "common/color.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
uniform sampler2D nmap;
uniform sampler2D nmap_flat;
uniform sampler2D nmap_ramp;
uniform sampler2D nmap_ramp_u;
void main() {
    vec4 texel = params.mode == MODE_FLAT_MAP ? texture(nmap_flat, v_uv)
               : params.mode == MODE_RAMP_MAP ? texture(nmap_ramp, v_uv)
               : params.mode == MODE_RAMP_U_MAP ? texture(nmap_ramp_u, v_uv) : texture(nmap, v_uv);
    // map_encoding = srgb_decoded shows the classic mistake: a normal map is data, not colour,
    // but an image loaded as sRGB (an _srgb format) is passed through the sRGB curve on
    // sampling, so 0.5 reads 0.214 and every normal leans towards -T and -B.
    if (params.map_encoding == MAP_ENCODING_SRGB_DECODED) texel.rgb = srgb_to_linear(texel.rgb);
    // TODO 1: decode the texel's RGB to the tangent-space normal n'. The map is "saved as range
    // compressed bitmap ([-1..1] mapped to [0..1])" (001_fe43b953f362fae7.txt L475): undo that
    // mapping. (A flat map stores (0.5, 0.5, 1), which must decode to n' = (0, 0, 1).)
    vec3 n_tangent = texel.xyz;
    // TODO 2: bring n' to world space with the tangent frame. The tangent space matrix of
    // 000_c9f7e5de708ecbb3.txt L2539 has T, B, N as its columns; here they are the interpolated
    // v_t, v_b, v_n (world space, no longer unit length after interpolation). Return a unit
    // vector: the lighting below expects one.
    vec3 n_mapped = n_tangent;
    vec3 n = params.mode == MODE_GEOMETRIC ? normalize(v_n) : n_mapped;
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    const float kSpecular = 0.35;   // highlight weight
    vec3 c = bump_blinn_phong(n, l, v, params.albedo, params.shininess, kSpecular);
    if (params.show == SHOW_NORMALS) c = n * 0.5 + 0.5;
    if (params.show == SHOW_HEIGHT) c = vec3(texture(nmap, v_uv).a);
    hdr = vec4(c, 1.0);
}
