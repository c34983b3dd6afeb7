#version 450
// Volumetric fog from a 3D texture (000_c9f7e5de708ecbb3.txt L1762-1776: a "3D voxel array of
// texture values", "Volumetric Fog"): the unit box [-1, 1]^3 holds density rho(p) = the texture
// `density` at (p + 1) / 2, shaped, times params.sigma (extinction per unit length). The view ray's part
// inside the box is marched with `steps` midpoint samples:
//     T = exp(-sum sigma rho_i dt),  L = sum T_i sigma rho_i dt (albedo ambient + sun T_sun,i P)
// with T_sun from an 8-sample march towards the light through the same texture, and an isotropic
// phase 1/(4 pi). Outputs the colour over the background and, in `transmit`, T alone (the tests'
// slab check: constant density gives T = exp(-sigma d) for a chord of length d).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 transmit;
uniform sampler3D density;

vec2 box_hit(vec3 o, vec3 d) {   // slab test against [-1, 1]^3: (t_near, t_far)
    vec3 inv = 1.0 / d, t0 = (-1.0 - o) * inv, t1 = (1.0 - o) * inv;
    vec3 lo = min(t0, t1), hi = max(t0, t1);
    return vec2(max(max(lo.x, lo.y), max(lo.z, 0.0)), min(min(hi.x, hi.y), hi.z));
}
// The texture's value shaped into puffs: smoothstep(0.4, 0.7, v), which keeps v = 1 at 1 (the
// homogeneous slab) and empties the space between puffs.
float rho(vec3 p) { return params.sigma * smoothstep(0.4, 0.7, texture(density, p * 0.5 + 0.5).r); }

void main() {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 o = frame.camera_pos.xyz, d = normalize(w.xyz / w.w - o);
    vec3 background = mix(vec3(0.55, 0.65, 0.8), vec3(0.15, 0.25, 0.45), clamp(d.y * 2.0, 0.0, 1.0));
    vec3 light = normalize(params.light_dir);
    vec2 t = box_hit(o, d);
    float tau = 0.0;
    vec3 L = vec3(0.0);
    if (t.y > t.x) {
        float dt = (t.y - t.x) / float(params.steps);
        for (int i = 0; i < params.steps; i++) {
            vec3 p = o + d * (t.x + (float(i) + 0.5) * dt);
            float s = rho(p);
            // light march to the box's far side along the light
            float ts = box_hit(p, light).y, dts = ts / 8.0, tau_s = 0.0;
            for (int j = 0; j < 8; j++) tau_s += rho(p + light * ((float(j) + 0.5) * dts)) * dts;
            vec3 in_light = params.ambient + params.sun * exp(-tau_s) / (4.0 * 3.14159265);
            L += exp(-(tau + 0.5 * s * dt)) * s * dt * params.albedo * in_light;
            tau += s * dt;
        }
    }
    float T = exp(-tau);
    color = vec4(background * T + L, 1.0);
    transmit = vec4(T, tau, 0.0, 1.0);
}
