#version 450
// Bump mapping from a height field (passes/bump/blinn_bump.glsl; 000_c9f7e5de708ecbb3.txt
// L2424-2488, 001_fe43b953f362fae7.txt L563-689, L741-780), four ways to get the normal:
//   blinn:  N' = N + h_u (N_n x P_v) + h_v (P_u x N_n), the heights in world units (params.height)
//   offset: square patch in TBN, N' = normalize(0, 0, 1) + D, D = (-h_u / k, -h_v / k, 0), 1/k = bump_depth
//   emboss: diffuse ~ l.z + (h(t) - h(t + shift l.xy)) / (shift k): two height lookups, no normal
//   none:   the interpolated normal (per-pixel lighting, presets/bump/per-pixel-lighting)
// h_u, h_v come from the baked offset map (bump/offset_map.frag), per unit of the map's t; the
// map is tiled, t = uv * tiling, so per unit of u: h_u = tiling.x * dh/dt_x (chain rule).
#include "bump/blinn_bump.glsl"
#include "bump/lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_n;
layout(location = 3) in vec3 v_pu;
layout(location = 4) in vec3 v_pv;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 normal_out;   // xyz: the world-space normal the lighting used; w: the diffuse factor (tests)
uniform sampler2D off_tiles;
uniform sampler2D off_flat;
uniform sampler2D off_ramp;
uniform sampler2D off_ramp_v;
const float kSpecular = 0.35;   // highlight weight, as presets/bump/normal-mapping

vec4 offsets(vec2 t) {
    if (params.heights == HEIGHTS_CONSTANT) return texture(off_flat, t);
    if (params.heights == HEIGHTS_RAMP) return texture(off_ramp, t);
    if (params.heights == HEIGHTS_RAMP_V) return texture(off_ramp_v, t);
    return texture(off_tiles, t);
}

void main() {
    vec3 N_n = normalize(v_n);
    vec3 P_u = v_pu, P_v = v_pv;
    // Tangent frame for the tangent-space modes (001 L693-722): T = P_u / |P_u| (made
    // orthogonal to the interpolated N_n), B along P_v: B = w (N_n x T), w the handedness.
    float w = dot(cross(P_u, P_v), N_n) < 0.0 ? -1.0 : 1.0;
    vec3 T = normalize(P_u - dot(P_u, N_n) * N_n), B = w * cross(N_n, T);
    mat3 tbn = mat3(T, B, N_n);

    vec4 o = offsets(v_uv * params.tiling);
    float h_u = o.y * params.tiling.x, h_v = o.z * params.tiling.y;   // per unit of u, v
    float k = 1.0 / params.bump_depth;
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);

    vec3 n = N_n;
    if (params.mode == MODE_BLINN) n = normalize(blinn_bump_normal(N_n, P_u, P_v, params.height * h_u, params.height * h_v));
    if (params.mode == MODE_OFFSET) n = normalize(tbn * offset_bump_normal_ts(h_u, h_v, k));
    vec2 terms = bump_blinn_phong_terms(n, l, v, params.shininess);
    if (params.mode == MODE_EMBOSS) {
        // Emboss replaces the diffuse term only; the highlight keeps the interpolated normal.
        vec3 l_ts = transpose(tbn) * l;
        float h_shift = offsets((v_uv + params.emboss_shift * l_ts.xy) * params.tiling).x;
        terms.x = max(emboss_diffuse(o.x, h_shift, params.emboss_shift, k, l_ts), 0.0);
    }
    vec3 c = bump_combine(params.albedo, terms.x, terms.y, kSpecular);
    if (params.show == SHOW_NORMALS) c = n * 0.5 + 0.5;
    if (params.show == SHOW_HEIGHT) c = vec3(o.x);
    hdr = vec4(c, 1.0);
    normal_out = vec4(n, terms.x);
}
