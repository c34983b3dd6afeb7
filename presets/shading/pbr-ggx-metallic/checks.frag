#version 450
// G = V * 4 (n.v)(n.l) for random n.v, n.l in [1e-5, 1] and roughness in [0.02, 1]: both forms.
#include "common/brdf.glsl"
#include "common/hash.glsl"
layout(location = 0) out vec2 checks;
void main() {
    vec3 h = hash_pcg3(vec3(gl_FragCoord.xy, 4.0));
    float nv = max(h.x, 1e-5), nl = max(h.y, 1e-5), r = 0.02 + 0.98 * h.z;
    checks = vec2(v_smith_ggx(nv, nl, r), v_schlick_ggx(nv, nl, r)) * 4.0 * nv * nl;
}
