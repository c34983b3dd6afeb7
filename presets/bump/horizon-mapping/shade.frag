#version 450
// Normal mapping with horizon-map shadows (001_fe43b953f362fae7.txt L965-975): the lighting of
// presets/bump/normal-mapping (n' = TBN (2 c - 1), Blinn-Phong from passes/bump/lighting.glsl
// with normal mapping's constants) times the horizon test of passes/bump/horizon.glsl for the
// light's tangent-space direction. shadows = false is normal mapping exactly.
#include "bump/lighting.glsl"
#include "bump/horizon.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
layout(location = 1) out float shadow;   // the horizon factor (tests)
uniform sampler2D nmap_tiles;
uniform sampler2D nmap_flat;
uniform sampler2D nmap_step;
uniform sampler2D hor_a_tiles;
uniform sampler2D hor_b_tiles;
uniform sampler2D hor_a_flat;
uniform sampler2D hor_b_flat;
uniform sampler2D hor_a_step;
uniform sampler2D hor_b_step;
const float kSpecular = 0.35;   // normal mapping's highlight weight (so shadows off = normal mapping)

void main() {
    mat3 tbn = mat3(normalize(v_t), normalize(v_b), normalize(v_n));
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    vec3 l_ts = transpose(tbn) * l;   // the light in the frame the horizons were baked in
    vec4 texel;
    float s;
    if (params.heights == HEIGHTS_FLAT) {
        texel = texture(nmap_flat, v_uv);
        s = horizon_shadow(hor_a_flat, hor_b_flat, v_uv, l_ts, params.softness);
    } else if (params.heights == HEIGHTS_STEP) {
        texel = texture(nmap_step, v_uv);
        s = horizon_shadow(hor_a_step, hor_b_step, v_uv, l_ts, params.softness);
    } else {
        texel = texture(nmap_tiles, v_uv);
        s = horizon_shadow(hor_a_tiles, hor_b_tiles, v_uv, l_ts, params.softness);
    }
    if (!params.shadows) s = 1.0;
    vec3 n = normalize(tbn * (texel.xyz * 2.0 - 1.0));
    vec2 t = bump_blinn_phong_terms(n, l, v, params.shininess);
    vec3 c = bump_combine(params.albedo, t.x * s, t.y * s, kSpecular);
    if (params.show == SHOW_SHADOW) c = vec3(s);
    if (params.show == SHOW_HORIZON) c = vec3(horizon_angle(hor_a_tiles, hor_b_tiles, v_uv, atan(l_ts.y, l_ts.x)) / 1.5707963);
    hdr = vec4(c, 1.0);
    shadow = s;
}
