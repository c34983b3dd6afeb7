#version 450
// Parallax mapping (passes/bump/parallax.glsl): the eye vector into tangent space, the lookup
// point shifted, then colour and normal read at T_n and lit (Blinn-Phong).
#include "bump/parallax.glsl"
#include "bump/lighting.glsl"   // the bump family's Blinn-Phong, one copy
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec2 offset;  // |T_n - T_0|, and its direction test (see below)
uniform sampler2D nmap;

vec3 tile_color(vec2 t) {  // a procedural albedo: tiles in two tones, dark grout
    vec2 cell = floor(t * 4.0);
    float h = texture(nmap, t).a;
    vec3 c = mod(cell.x + cell.y, 2.0) < 1.0 ? vec3(0.75, 0.5, 0.32) : vec3(0.6, 0.62, 0.66);
    return mix(vec3(0.12, 0.1, 0.09), c, smoothstep(0.2, 0.6, h));
}

void main() {
    mat3 tbn = mat3(normalize(v_t), normalize(v_b), normalize(v_n));
    vec3 V = normalize(transpose(tbn) * (frame.camera_pos.xyz - v_world));  // tangent space
    vec2 t = params.mode == MODE_PLAIN ? v_uv : parallax_uv(nmap, v_uv, V, params.scale, params.mode == MODE_LIMITED);
    // x: |T_n - T_0|. y: (T_n - T_0).V.xy signed by h_n: a point above the carrier (h_n > 0) is
    // looked up towards the eye, one below it away from it (001 L528-532), so y >= 0 everywhere.
    offset = vec2(length(t - v_uv), dot(t - v_uv, V.xy) * sign(texture(nmap, v_uv).a - 0.5));
    vec3 n = normalize(tbn * (texture(nmap, t).xyz * 2.0 - 1.0));
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    const float kShininess = 48.0, kSpecular = 0.25;
    vec3 c = bump_blinn_phong(n, l, v, tile_color(t), kShininess, kSpecular);
    if (params.show == SHOW_OFFSET) c = vec3(offset.x / max(0.5 * params.scale, 1e-6));
    hdr = vec4(c, 1.0);
}
