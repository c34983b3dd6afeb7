#version 450
// Volumetric fog from a 3D texture (000_c9f7e5de708ecbb3.txt L1762-1776: a "3D voxel array of
// texture values", "Volumetric Fog"): the unit box [-1, 1]^3 holds density rho(p) = the texture
// `density` at (p + 1) / 2, shaped, times params.sigma (extinction per unit length). The view ray's part
// inside the box is marched with `steps` midpoint samples:
//     T = exp(-sum sigma rho_i dt),  L = sum T_i sigma rho_i dt (albedo ambient + sun T_sun,i P)
// with T_sun from the baked light volume (light.comp: a 16-sample march per voxel), and an isotropic
// phase 1/(4 pi). Outputs the colour over the background and, in `transmit`, T alone (the tests'
// slab check: constant density gives T = exp(-sigma d) for a chord of length d).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 transmit;
uniform sampler3D density;

uniform sampler3D light;     // the sun's transmittance per voxel (light.comp, baked)
#include "fog_density.glsl"

void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 o = frame.camera_pos.xyz, d = normalize(w.xyz / w.w - o);
    vec3 background = mix(vec3(0.55, 0.65, 0.8), vec3(0.15, 0.25, 0.45), clamp(d.y * 2.0, 0.0, 1.0));
    vec2 t = box_hit(o, d);
    float tau = 0.0;
    vec3 L = vec3(0.0);
    if (t.y > t.x) {
        float dt = (t.y - t.x) / float(params.steps);
        for (int i = 0; i < params.steps; i++) {
            vec3 p = o + d * (t.x + (float(i) + 0.5) * dt);
            float s = rho(p);
            vec3 in_light = params.ambient + params.sun * texture(light, p * 0.5 + 0.5).r / (4.0 * 3.14159265);
            L += exp(-(tau + 0.5 * s * dt)) * s * dt * params.albedo * in_light;
            tau += s * dt;
        }
    }
    float T = exp(-tau);
    color = vec4(background * T + L, 1.0);
    transmit = vec4(T, tau, 0.0, 1.0);
}
