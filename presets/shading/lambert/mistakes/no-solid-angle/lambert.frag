#version 450
// Lambert shading, 000_c9f7e5de708ecbb3.txt L893-898 (f_r = c_d / pi: L1011):
//     L_o = c_d * max(n.l, 0) * I_L
// "furnace" mode instead integrates the rendering equation numerically under a uniform white
// environment (L_i = 1 everywhere): L_o = integral f_r L_i cos(theta) dw with f_r = c_d / pi
// from passes/common/brdf.glsl. With c_d = 1 the result must be 1: the white furnace test.
#include "common/brdf.glsl"
#include "common/sampling.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 0) out vec4 color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 lo;
    if (params.mode == MODE_FURNACE) {
        mat3 tbn = basis_from_normal(n);
        int m = params.samples;
        vec3 sum = vec3(0.0);
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                vec3 wi = tbn * hemisphere_uniform(i, j, m);
                float cos_t = max(dot(n, wi), 0.0);
                sum += brdf_lambert(params.albedo) * 1.0 * cos_t;  // L_i = 1
            }
        lo = sum / float(m * m);  // each sample covers 2 pi / m^2 sr
    } else {
        // pi * f_r = c_d: the textbook formula without the 1/pi, written through the BRDF.
        vec3 l = normalize(params.light_dir);
        lo = kPi * brdf_lambert(params.albedo) * max(dot(n, l), 0.0) * params.irradiance;
    }
    color = vec4(lo, 1.0);
}
