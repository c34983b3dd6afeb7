#version 450
// EXERCISE — Lambert shading (000_c9f7e5de708ecbb3.txt L893-898) and the white furnace.
// Fill in the two TODO blocks, then check your work against the reference:
//     passlab run   shading/lambert --exercise presets/shading/lambert/exercise   (live, hot reload)
//     passlab grade shading/lambert --exercise presets/shading/lambert/exercise   (the test cases)
// The helpers you need are in passes/common/brdf.glsl (brdf_lambert(c_d) = c_d / pi, kPi) and
// passes/common/sampling.glsl (basis_from_normal, hemisphere_uniform).
#include "common/brdf.glsl"
#include "common/sampling.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 0) out vec4 color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 lo = vec3(0.0);
    if (params.mode == MODE_FURNACE) {
        // Integrate the rendering equation under a uniform white environment (L_i = 1):
        //     L_o = integral over the hemisphere of f_r * L_i * cos(theta) dw
        // with m x m stratified directions from hemisphere_uniform(i, j, m) in the frame of n.
        mat3 tbn = basis_from_normal(n);
        int m = params.samples;
        vec3 sum = vec3(0.0);
        for (int i = 0; i < m; ++i)
            for (int j = 0; j < m; ++j) {
                vec3 wi = tbn * hemisphere_uniform(i, j, m);
                // TODO 1: add this direction's contribution f_r * L_i * cos(theta) to sum.
            }
        // TODO 2: each of the m * m samples stands for an equal part of the hemisphere's solid
        // angle. Scale sum by it (what is the solid angle of a hemisphere?).
        lo = sum;
    } else {
        // TODO 3: one directional light of irradiance params.irradiance from params.light_dir (L893-898):
        //     L_o = c_d * max(n.l, 0) * I_L     (written through the BRDF: pi * f_r = c_d)
        // and remember that light_dir is not normalised.
    }
    color = vec4(lo, 1.0);
}
