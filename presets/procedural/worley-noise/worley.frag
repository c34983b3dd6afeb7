#version 450
// Worley noise (passes/common/noise.glsl, 004_9a40ad89bdfc582a.txt L508-579) and its variants:
//   F_k;  sum a_i F_i (004 L527-529);  sum p^i F1(2^i x) (004 L531-533, p = 0.5).
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 field;
layout(location = 1) out vec2 diffs;
void main() {
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0) * params.frequency + 100.0;
    vec3 f = worley_noise(p);
    float v = params.variant == VARIANT_F1            ? f.x
              : params.variant == VARIANT_F2          ? f.y
              : params.variant == VARIANT_F2_MINUS_F1 ? f.y - f.x
              : params.variant == VARIANT_MIX         ? dot(f, vec3(0.5, 0.3, 0.2))
                                                      : 0.0;
    if (params.variant == VARIANT_FRACTAL) {
        float amp = 1.0, norm = 0.0;
        for (int i = 0; i < 4; ++i, amp *= 0.5) v += amp * worley_noise(p * exp2(float(i))).x, norm += amp;
        v /= norm;
    }
    field = vec4(f, v);
    diffs = vec2(f.y - f.x, f.z - f.y);
}
