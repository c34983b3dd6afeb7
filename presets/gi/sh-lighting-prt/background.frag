#version 450
// The environment behind the scene. BOTH = 0 (the view): `hdr` shows the environment itself or
// its 16-coefficient reconstruction sum_k L_k y_k(w) (what the objects are lit by), as
// params.background picks, and `coverage` is cleared (the draws write 1). BOTH = 1 (the test-only
// pass `verify`): `env_img` gets the environment and `sh_img` the reconstruction, which the
// round-trip tests compare.
layout(location = 0) in vec2 uv;
#if BOTH
layout(location = 0) out vec4 env_img;
layout(location = 1) out vec4 sh_img;
#else
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 coverage;
#endif
layout(std430) readonly buffer EnvSh { vec4 c[16]; } env_sh;
#include "gi/sh.glsl"
#include "env.glsl"

vec3 reconstruct(vec3 w) {
    float y[16];
    sh_eval(w, 4, y);
    vec3 rec = vec3(0.0);
    for (int k = 0; k < 16; ++k) rec += env_sh.c[k].rgb * y[k];
    return rec;
}

void main() {
    vec4 a = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 0.0, 1.0), b = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    vec3 w = normalize(b.xyz / b.w - a.xyz / a.w);
#if BOTH
    env_img = vec4(env_radiance(w), 1.0);
    sh_img = vec4(reconstruct(w), 1.0);
#else
    hdr = vec4(params.background == BACKGROUND_SH ? reconstruct(w) : env_radiance(w), 1.0);
    coverage = vec4(0.0);
#endif
}
