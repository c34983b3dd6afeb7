// The reflective shadow map's gather (Dachsbacher and Stamminger 2005; 000_c9f7e5de708ecbb3.txt
// L5332-5359: "each pixel is a small light source ... gather illumination from the RSM"): every
// RSM texel p is a diffuse emitter of reflected flux Phi_p at x_p with normal n_p, and the
// irradiance it sends to a receiver x with normal n is
//
//   E_p(x) = Phi_p / pi * max(0, n_p . (x - x_p)) * max(0, n . (x_p - x)) / |x - x_p|^4
//
// (both cosines, written unnormalised, so the two |x - x_p| they carry make the fourth power).
// Near a texel the point-light 1/d^2 is singular; the texel is a patch of area A_p, whose
// on-axis irradiance is Phi_p/pi * 1/(d^2 + A_p/pi) (a disc's form factor), so the d^4 becomes
// d^2 (d^2 + A_p/pi): exact far away, bounded near. No visibility: RSMs have no indirect
// shadows (L5355-5359). The graph binds the RSM as `rsm_flux`, `rsm_normal`, `rsm_pos`.
#ifndef RSM_GATHER_GLSL
#define RSM_GATHER_GLSL
uniform sampler2D rsm_flux, rsm_normal, rsm_pos;

vec3 rsm_texel_irradiance(vec3 x, vec3 n, vec3 flux, vec3 xp, vec3 np, float area) {
    // TODO: the irradiance one RSM texel sends to the receiver (000_c9f7e5de708ecbb3.txt
    // L5336-5341: "each pixel is small light source", its flux stored "during rendering of
    // shadow map"; Dachsbacher and Stamminger 2005, eq. 1):
    //     E_p(x) = Phi_p / pi * max(0, n_p . (x - x_p)) * max(0, n . (x_p - x)) / |x - x_p|^4
    // The two dot products are unnormalised, each carrying one |x - x_p|: with the d^2 of the
    // point light that makes d^4. Both cosines are clamped at 0: the texel emits only into the
    // hemisphere of its normal n_p, the receiver takes light only from the front of n.
    // Near the texel d^4 explodes: treat the texel as a patch of area `area` and replace
    // d^4 by d^2 (d^2 + area / pi) (a disc's on-axis form factor), which is exact far away.
    return vec3(0.0);
}

// E(x) = sum over every texel of the RSM.
vec3 rsm_irradiance(vec3 x, vec3 n) {
    ivec2 size = textureSize(rsm_flux, 0);
    vec3 e = vec3(0.0);
    for (int y = 0; y < size.y; ++y)
        for (int i = 0; i < size.x; ++i) {
            vec3 flux = texelFetch(rsm_flux, ivec2(i, y), 0).rgb;
            vec4 xp = texelFetch(rsm_pos, ivec2(i, y), 0);
            vec3 np = texelFetch(rsm_normal, ivec2(i, y), 0).xyz;
            e += rsm_texel_irradiance(x, n, flux, xp.xyz, np, xp.w);
        }
    return e;
}

// What the shared low-res gather and compose passes call (gi/rsm_lowres.comp, gi/rsm_compose.frag).
vec3 gi_irradiance(vec3 x, vec3 n) { return rsm_irradiance(x, n); }
#endif
