#version 450
// A gloss map (000_c9f7e5de708ecbb3.txt L2446-2472, 004_9a40ad89bdfc582a.txt L119-125,
// 001_fe43b953f362fae7.txt L874-883: "gloss map defines where to apply specular"): Phong with a
// specular coefficient read from a texture,
//     I_out = (r_d cos(phi) + r_s(u, v) cos(theta)^p) I_in                      (004 L123)
// phi: angle between n and l; theta: between the mirror direction r = 2n(n.l) - l and v.
// Multitexturing (000 L2148-2155): several samplers in one shader, combined freely, and the
// indirect (dependent) lookup — "1st texture lookup is used to index into 2nd texture":
// gloss = indirect reads a material index from id_map (NEAREST: indices must not be blended)
// and looks up (r_s, p) in the palette with it.
// The specular is gated by n.l > 0 (stated: the printed formula is not, and would light the
// back of the teapot where v.r > 0 with the light below the horizon).
#include "common/brdf.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D diffuse_map;
uniform sampler2D gloss_map;
uniform sampler2D gloss_zero;
uniform sampler2D gloss_one;
uniform sampler2D id_map;
uniform sampler2D palette;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;                        // inside the open lid rim
    vec3 l = normalize(params.light_dir);
    vec3 v = normalize(frame.camera_pos.xyz - v_world);
    vec3 r_d = texture(diffuse_map, v_uv).rgb;          // first texture: colour
    float cos_phi = max(dot(n, l), 0.0);
    vec3 i_out = r_d * cos_phi;
    if (params.gloss != GLOSS_NONE) {
        float p = params.exponent, r_s;
        if (params.gloss == GLOSS_MAP) r_s = texture(gloss_map, v_uv).r;       // second texture
        else if (params.gloss == GLOSS_ZERO) r_s = texture(gloss_zero, v_uv).r;
        else if (params.gloss == GLOSS_ONE) r_s = texture(gloss_one, v_uv).r;
        else if (params.gloss == GLOSS_UNIFORM) r_s = 1.0;                       // no texture
        else {                                                                   // dependent
            vec2 material = texture(palette, vec2(texture(id_map, v_uv).r, 0.5)).rg;
            r_s = material.x;
            p = material.y;
        }
        i_out += r_s * phong_lobe(v, phong_mirror(n, l), p) * step(0.0, dot(n, l));
    }
    hdr = vec4(i_out * params.light_intensity + params.ambient * r_d, 1.0);
}
