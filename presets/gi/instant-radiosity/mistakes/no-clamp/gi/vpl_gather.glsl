// The instant-radiosity gather (000_c9f7e5de708ecbb3.txt L5163-5172: "pass 2: deferred rendering,
// render considering all the VPL and their shadow maps"). VPL i at y_i with normal n_i reflects
// the flux Phi_i as a diffuse point emitter, radiance Phi_i/pi * cos; the irradiance at x with
// normal n is
//
//   E(x) = sum_i Phi_i / pi * V_i(x) * max(0, cos theta_i) max(0, cos theta_x) / max(d^2, c^2)
//
// with d = |x - y_i| and V_i from VPL i's paraboloid shadow map. The 1/d^2 of a point light is
// singular next to the VPL: unclamped, a VPL in a corner paints a bright blotch on the wall it
// touches (the catalogue's pitfall); clamping d at c (params.clamp) bounds each VPL's share and
// loses a little energy near it. Then L1 = rho/pi * E.
#ifndef PASSLAB_GI_VPL_GATHER_GLSL
#define PASSLAB_GI_VPL_GATHER_GLSL
#include "gi/vpl.glsl"
uniform sampler2DArray vpl_maps;

// Whether x is seen from VPL v: its distance along the paraboloid direction against the map, with
// a bias of a few map texels (the paraboloid's texels span up to 4/size radians at the rim).
float ir_visibility(Vpl v, uint slot, vec3 x, vec3 n) {
    vec4 m = vpl_paraboloid(x, v.position.xyz, normalize(v.normal.xyz + vec3(0.0, 0.0, 1e-7)));
    if (m.w <= 0.0) return 0.0;
    vec2 uv = vec2(0.5 + 0.5 * m.x, 0.5 - 0.5 * m.y);  // vpl_map.vert rasterises (s, -t): Vulkan NDC y grows downwards
    float stored = texture(vpl_maps, vec3(uv, float(slot))).r;
    float bias = (0.03 + 0.06 * m.z * VPL_FAR) / VPL_FAR;
    return m.z - bias <= stored ? 1.0 : 0.0;
}

vec3 ir_vpl_irradiance(Vpl v, uint slot, vec3 x, vec3 n) {
    vec3 w = x - v.position.xyz;
    float d2 = dot(w, w);
    w *= inversesqrt(d2);
    float g = max(dot(v.normal.xyz, w), 0.0) * max(dot(n, -w), 0.0) / d2;
    return g > 0.0 ? v.flux.rgb / 3.14159265 * g * ir_visibility(v, slot, x, n) : vec3(0.0);
}

vec3 ir_irradiance(vec3 x, vec3 n) {
    vec3 e = vec3(0.0);
    for (uint s = 0u; s < vpl_args.slots; ++s) {
        Vpl v = vpls.vpl[s];
        if (v.position.w > 0.0) e += ir_vpl_irradiance(v, s, x, n);
    }
    return e;
}

// What the shared low-res gather and compose passes call (gi/rsm_lowres.comp, gi/rsm_compose.frag).
vec3 gi_irradiance(vec3 x, vec3 n) { return ir_irradiance(x + n * 1e-3, n); }
#endif
