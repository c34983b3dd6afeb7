#version 450
// Relief mapping (passes/bump/parallax.glsl; 001_fe43b953f362fae7.txt L984-1023, parallax
// occlusion mapping in 000_c9f7e5de708ecbb3.txt L2623-2635): find the eye ray's intersection
// with the height field, then texture, normal and lighting at the hit.
#include "bump/parallax.glsl"
#include "bump/lighting.glsl"   // the bump family's Blinn-Phong, one copy
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
layout(location = 1) out float error;
uniform sampler2D nmap_tiles;
uniform sampler2D nmap_top;
uniform sampler2D nmap_step;

vec3 find(vec2 t0, vec3 V) {
    if (params.heights == HEIGHTS_TOP) return relief_intersect(nmap_top, t0, V, params.depth_scale, params.linear_steps, params.binary_steps);
    if (params.heights == HEIGHTS_STEP) return relief_intersect(nmap_step, t0, V, params.depth_scale, params.linear_steps, params.binary_steps);
    return relief_intersect(nmap_tiles, t0, V, params.depth_scale, params.linear_steps, params.binary_steps);
}
vec4 at(vec2 t) {
    return params.heights == HEIGHTS_TOP ? texture(nmap_top, t) : params.heights == HEIGHTS_STEP ? texture(nmap_step, t) : texture(nmap_tiles, t);
}

// The step field's true hit depth for the ray from t0 with uv travel `delta` per unit depth:
// depth 0 while u < 0.5 (the plateau), else the floor (1) unless the ray crosses u = 0.5 first.
float true_step_depth(vec2 t0, vec2 delta) {
    if (t0.x < 0.5) return 0.0;
    if (delta.x < 0.0) return min(1.0, (t0.x - 0.5) / -delta.x);
    return 1.0;
}

void main() {
    mat3 tbn = mat3(normalize(v_t), normalize(v_b), normalize(v_n));
    vec3 V = normalize(transpose(tbn) * (frame.camera_pos.xyz - v_world));
    vec3 hit = find(v_uv, V);
    vec2 t = hit.xy;
    vec4 texel = at(t);
    vec3 n = normalize(tbn * (texel.xyz * 2.0 - 1.0));
    vec2 cell = floor(t * 4.0);
    vec3 albedo = mod(cell.x + cell.y, 2.0) < 1.0 ? vec3(0.75, 0.5, 0.32) : vec3(0.6, 0.62, 0.66);
    albedo = mix(vec3(0.12, 0.1, 0.09), albedo, smoothstep(0.2, 0.6, texel.a));
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    const float kShininess = 48.0, kSpecular = 0.25;
    hdr = vec4(bump_blinn_phong(n, l, v, albedo, kShininess, kSpecular), 1.0);
    vec2 delta = -V.xy / max(V.z, 1e-4) * params.depth_scale;
    float bound = (1.0 / float(params.linear_steps)) / exp2(float(params.binary_steps));
    error = params.heights == HEIGHTS_STEP ? abs(hit.z - true_step_depth(v_uv, delta)) / bound : 0.0;
}
