#version 450
// VPL generation (000_c9f7e5de708ecbb3.txt L5163-5170: "shoot photons from light source, follow
// them through scene, at each hit point create VPL, Russian roulette to end path"). One thread per
// path p of `paths`:
//   - a direction in the spot's 60-degree cone, Hammersley-stratified over the cone's solid angle
//     Omega = 2 pi (1 - cos 60) = pi; the path carries Phi_path = I(w) Omega / paths;
//   - at each hit y_i (traced through the BVH) a VPL with the flux its surface reflects,
//     Phi_i = rho_i * Phi_arriving;
//   - it continues along a cosine-distributed direction with probability q = mean(rho_i), and
//     the survivor's flux is divided by q (Russian roulette: paths die in proportion rho^i, the
//     seed's "distributed according to rho^i", L5190-5193), up to `bounces` VPLs per path.
layout(local_size_x = 64) in;
#include "gi/vpl_trace.glsl"
#include "gi/vpl.glsl"
void main() {
    int paths = params.paths;
    int p = int(gl_GlobalInvocationID.x);
    if (p >= paths) return;
    for (int b = 0; b < params.bounces; ++b)
        if (b * paths + p < VPL_SLOTS) vpls.vpl[b * paths + p] = Vpl(vec4(0.0), vec4(0.0), vec4(0.0));
    vec2 u = vec2((float(p) + 0.5) / float(paths), vpl_radical_inverse(uint(p)));
    float cos_t = 1.0 - u.x * (1.0 - CORNELL_CONE_OUTER), sin_t = sqrt(1.0 - cos_t * cos_t);
    float phi = 6.2831853 * u.y;
    vec3 rd = normalize(vec3(sin_t * cos(phi), -cos_t, sin_t * sin(phi)));  // about -Y, the spot's axis
    const float omega = 6.2831853 * (1.0 - CORNELL_CONE_OUTER);
    vec3 phi_in = cornell_light_intensity(rd) * omega / float(paths);
    vec3 ro = CORNELL_LIGHT_POS;
    for (int b = 0; b < params.bounces; ++b) {
        VplSurface y = vpl_trace(ro, rd, 1e-4);
        if (!y.hit || b * paths + p >= VPL_SLOTS) return;
        vec3 reflected = y.albedo * phi_in;
        vpls.vpl[b * paths + p] = Vpl(vec4(y.p, 1.0), vec4(y.n, 0.0), vec4(reflected, 0.0));
        float q = (y.albedo.r + y.albedo.g + y.albedo.b) / 3.0;
        uint h = vpl_hash(uint(p) * 7919u + uint(b) * 104729u + 17u);
        if (float(h) * 2.3283064e-10 >= q) return;
        phi_in = reflected / q;
        ro = y.p + y.n * 1e-4;
        rd = vpl_cosine_direction(y.n, vec2(vpl_radical_inverse(uint(p) ^ (uint(b) * 0x9e3779b9u)), float(vpl_hash(h)) * 2.3283064e-10));
    }
}
