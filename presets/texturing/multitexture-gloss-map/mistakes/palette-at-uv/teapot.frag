#version 450
// EXERCISE — gloss map and dependent lookup (000_c9f7e5de708ecbb3.txt L2148-2156, L2446-2472;
// 004_9a40ad89bdfc582a.txt L119-125; 001_fe43b953f362fae7.txt L874-883: "gloss map defines
// where to apply specular"). Phong with a specular coefficient read from a texture,
//     I_out = (r_d cos(phi) + r_s(u, v) cos(theta)^p) I_in                      (004 L123)
// phi: angle between n and l; theta: between the mirror direction r = 2n(n.l) - l and v.
// You write the indirect lookup of gloss = indirect (TODO 1) and the specular term with its
// gloss (TODO 2); the textures, the diffuse term and the rest are given.
//     passlab run   texturing/multitexture-gloss-map --exercise presets/texturing/multitexture-gloss-map/exercise
//     passlab grade texturing/multitexture-gloss-map --exercise presets/texturing/multitexture-gloss-map/exercise
// common/brdf.glsl has phong_mirror(n, l) = 2n(n.l) - l and phong_lobe(v, r, p) = max(v.r, 0)^p.
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
        else {
            // TODO 1: the dependent lookup (000 L2152-2153, "1st texture lookup is used to
            // index into 2nd texture"): id_map's red channel at this point is a material index,
            // already stored as the palette's texel-centre coordinate (index + 0.5) / 4; the
            // palette (4 x 1) holds each material's r_s in red and its Phong exponent p in green.
            // Set both r_s and p from the texel the index selects.
            vec2 material = texture(palette, v_uv).rg;
            r_s = material.x;
            p = material.y;
        }
        // TODO 2: the specular term of the gloss-mapped Phong (004 L123, 001 L874-883): r_s says
        // where, and how strongly, to apply specular. Add to i_out
        //     r_s(u, v) cos(theta)^p
        // with cos(theta) = v . r, r the mirror direction of l about n; only where the light is
        // above the surface (n.l > 0: the printed formula is not gated, see the README).
        i_out += r_s * phong_lobe(v, phong_mirror(n, l), p) * step(0.0, dot(n, l));
    }
    hdr = vec4(i_out * params.light_intensity + params.ambient * r_d, 1.0);
}
